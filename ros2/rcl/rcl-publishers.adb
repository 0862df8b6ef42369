with Ada.Streams;
with Ada.Strings.Unbounded;
with ROSIDL.CDR;
with ROSIDL.Typesupport;
with RCL.Contexts;
with RCL.Event_Watches;
with RCL.Graph;
with RCL.Graph_Announcements;

package body RCL.Publishers is

   use Ada.Strings.Unbounded;

   procedure Publish_Raw (This : Publisher; Data : RCL.DDS.Byte_Array) is
   begin
      if RCL.Contexts.Is_Shutdown then
         raise ROS_Exception with "publishing on " & Topic (This) & ": the context is shut down";
      end if;
      RCL.DDS.Write (This.W, Data);
   end Publish_Raw;

   procedure Publish (This : in out Publisher; Msg : ROSIDL.Dynamic.Message) is
   begin
      if not ROSIDL.Dynamic.Is_Initialised (Msg)
        or else not ((This.Typed
                      and then ROSIDL.Typesupport."=" (ROSIDL.Dynamic.Support (Msg),
                                                       This.Support))
                     or else ROSIDL.Typesupport.DDS_Type_Name (ROSIDL.Dynamic.Support (Msg))
                             = Type_Name (This))
      then
         raise ROS_Exception with "publishing on " & Topic (This) & ": a "
           & ROSIDL.Dynamic.Type_Name (Msg) & " message, the topic has type "
           & Type_Name (This);
      end if;
      if RCL.Contexts.Is_Shutdown then
         raise ROS_Exception with "publishing on " & Topic (This) & ": the context is shut down";
      end if;
      declare
         procedure Fill
           (Buffer : out Ada.Streams.Stream_Element_Array;
            Last   : out Ada.Streams.Stream_Element_Offset) is
         begin
            ROSIDL.CDR.Encode (Msg, Buffer, Last);
         end Fill;
      begin
         --  Encoded straight into the DDS sample (no copy, no stack buffer).
         RCL.DDS.Write_Filled (This.W, ROSIDL.CDR.Encoded_Size (Msg), Fill'Access);
      end;
   end Publish;

   function Topic (This : Publisher) return String is (To_String (This.Topic));

   function Type_Name (This : Publisher) return String is (RCL.DDS.Type_Name (This.W));

   function GID (This : Publisher) return RCL.DDS.GUID is (RCL.DDS.Endpoint_GUID (This.W));

   function Matched_Subscriptions (This : Publisher) return Natural is
     (RCL.DDS.Matched_Readers (This.W));

   overriding procedure Finalize (This : in out Publisher) is
   begin
      if RCL.DDS.Is_Open (This.W) then
         RCL.Event_Watches.Unregister_Publisher (This);
         RCL.Graph_Announcements.Remove_Writer (This.Node, RCL.DDS.Endpoint_GUID (This.W));
      end if;
      This.Node := RCL.Graph.No_Node;
   exception
      when others =>
         null;
   end Finalize;

end RCL.Publishers;
