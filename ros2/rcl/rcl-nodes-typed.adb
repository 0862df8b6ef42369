with Ada.Streams;
with Ada.Unchecked_Deallocation;
with RCL.Contexts;
with RCL.Publisher_Writers;
with ROSIDL.Type_Hashes;
with System.Address_To_Access_Conversions;

package body RCL.Nodes.Typed is

   function Publish
     (Node  : in out Nodes.Node'Class;
      Topic : String;
      QoS   : RCL.QoS.Profile := RCL.QoS.Default) return RCL.Publishers.Publisher is
   begin
      ROSIDL.Type_Hashes.Register (Handling.DDS_Type_Name, Handling.Type_Hash);
      return Node.Publish_Raw (Handling.DDS_Type_Name, Topic, QoS);
   end Publish;

   procedure Publish (Pub : RCL.Publishers.Publisher; Msg : Message) is

      procedure Fill
        (Buffer : out Ada.Streams.Stream_Element_Array;
         Last   : out Ada.Streams.Stream_Element_Offset) is
      begin
         Handling.Encode (Msg, Buffer, Last);
      end Fill;

   begin
      if RCL.Publishers.Type_Name (Pub) /= Handling.DDS_Type_Name then
         raise ROS_Exception with "publishing on " & RCL.Publishers.Topic (Pub) & ": a "
           & Handling.Full_Name & " message, the topic has type "
           & RCL.Publishers.Type_Name (Pub);
      elsif RCL.Contexts.Is_Shutdown then
         raise ROS_Exception with "publishing on " & RCL.Publishers.Topic (Pub)
           & ": the context is shut down";
      end if;
      RCL.DDS.Write_Filled (RCL.Publisher_Writers.Writer (Pub).all, Handling.Encoded_Size (Msg),
                            Fill'Access);
   end Publish;

   type Callback_Access is access procedure
     (Node : in out Nodes.Node'Class;
      Msg  : Message;
      Info : ROSIDL.Message_Info);

   --  Deliveries of one subscription may run in several executor tasks at
   --  once: the first takes the kept record (Cache_Lock), the others decode
   --  into their own.

   --  One per subscription, allocated at Subscribe (the instance may be
   --  nested in a subprogram: its types cannot extend the library-level
   --  Handler, hence RCL.Nodes.Subscribe_Closure).
   type Slot is record
      Callback : Callback_Access;
      Kept     : Message;
      Lock     : Cache_Lock;
   end record;

   package Slot_Addresses is new System.Address_To_Access_Conversions (Slot);

   procedure Deliver
     (State : System.Address;
      Node  : in out Nodes.Node'Class;
      Data  : RCL.DDS.Byte_Array;
      Info  : ROSIDL.Message_Info)
   is
      This : Slot renames Slot_Addresses.To_Pointer (State).all;

      procedure Use_Kept is
      begin
         Handling.Decode (Data, This.Kept);
         This.Callback (Node, This.Kept, Info);
      end Use_Kept;

      procedure Use_Own is
         Own : Message;
      begin
         Handling.Decode (Data, Own);
         This.Callback (Node, Own, Info);
      end Use_Own;
   begin
      Deliver_Decoded (This.Lock, Use_Kept'Access, Use_Own'Access);
   end Deliver;

   type Slot_Access is access all Slot;
   procedure Free is new Ada.Unchecked_Deallocation (Slot, Slot_Access);

   procedure Release (State : System.Address) is
      S : Slot_Access := Slot_Access (Slot_Addresses.To_Pointer (State));
   begin
      Free (S);
   end Release;

   procedure Subscribe
     (Node     : in out Nodes.Node'Class;
      Topic    : String;
      Callback : not null access procedure
        (Node : in out Nodes.Node'Class;
         Msg  : Message;
         Info : ROSIDL.Message_Info);
      QoS      : RCL.QoS.Profile := RCL.QoS.Default)
   is
      Stored : constant Callback_Access with Import, Address => Callback'Address;
      --  GNAT: the same subprogram access, kept beyond the call (see spec).
      S : constant Slot_Access := new Slot;
   begin
      S.Callback := Stored;
      ROSIDL.Type_Hashes.Register (Handling.DDS_Type_Name, Handling.Type_Hash);
      Node.Subscribe_Closure (Handling.DDS_Type_Name, Topic, Deliver'Access,
                              Slot_Addresses.To_Address (Slot_Addresses.Object_Pointer (S)),
                              Release'Access, QoS);
      --  On failure the handler, then the slot, were released.
   end Subscribe;

end RCL.Nodes.Typed;
