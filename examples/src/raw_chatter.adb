--  Raw-bytes pub/sub on /chatter (std_msgs/String), used by the interop
--  tests before the message layer exists:
--     raw_chatter pub COUNT   publishes "Hello World: N" COUNT times (10 Hz)
--     raw_chatter sub COUNT   prints "heard: <text>" for COUNT messages
--  std_msgs/String CDR is built and read by hand here (a test fixture, not
--  the library's codec).
with Ada.Command_Line;
with Ada.Streams;
with Ada.Text_IO;
with Interfaces;
with ROSIDL;
with RCL.DDS;
with RCL.Nodes;
with RCL.Publishers;
with RCL.Timers;

procedure Raw_Chatter is

   use Ada.Streams;
   use type Interfaces.Unsigned_32;

   Type_Name : constant String := "std_msgs::msg::dds_::String_";
   Mode      : constant String := Ada.Command_Line.Argument (1);
   Count     : constant Positive := Positive'Value (Ada.Command_Line.Argument (2));
   Heard     : Natural := 0 with Atomic;
   Sent      : Natural := 0 with Atomic;
   --  Set by callbacks (through the executor): read afresh in the loops.

   function Encode (Text : String) return Stream_Element_Array is
      Len    : constant Interfaces.Unsigned_32 := Text'Length + 1;
      Size   : constant Stream_Element_Offset := Stream_Element_Offset (4 + 4 + Len);
      Padded : constant Stream_Element_Offset := (Size + 3) / 4 * 4;
      Result : Stream_Element_Array (1 .. Padded) := [2 => 1, others => 0];
   begin
      for I in 0 .. 3 loop
         Result (5 + Stream_Element_Offset (I)) :=
           Stream_Element (Interfaces.Shift_Right (Len, 8 * I) and 16#FF#);
      end loop;
      for I in Text'Range loop
         Result (9 + Stream_Element_Offset (I - Text'First)) := Character'Pos (Text (I));
      end loop;
      return Result;
   end Encode;

   function Decode (Data : Stream_Element_Array) return String is
      Len : Natural := 0;
   begin
      if Data'Length < 8 or else Data (Data'First + 1) /= 1 then
         return "<not little-endian CDR>";
      end if;
      for I in reverse 0 .. 3 loop
         Len := Len * 256 + Natural (Data (Data'First + 4 + Stream_Element_Offset (I)));
      end loop;
      if Len = 0 or else Data'Length < Stream_Element_Offset (8 + Len) then
         return "<bad length" & Len'Image & ">";
      end if;
      declare
         Result : String (1 .. Len - 1);
      begin
         for I in Result'Range loop
            Result (I) := Character'Val (Data (Data'First + 7 + Stream_Element_Offset (I)));
         end loop;
         return Result;
      end;
   end Decode;

   Node : RCL.Nodes.Node := RCL.Nodes.Init ("raw_chatter");

   procedure On_Message
     (Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Ada.Text_IO.Put_Line ("heard: " & Decode (Data));
      Heard := Heard + 1;
   end On_Message;

begin
   if Mode = "sub" then
      Node.Subscribe_Raw (Type_Name, "chatter", On_Message'Access);
      Ada.Text_IO.Put_Line ("ready");
      while Heard < Count loop
         Node.Spin (During => 0.2);
      end loop;
   else
      declare
         Pub : constant RCL.Publishers.Publisher := Node.Publish_Raw (Type_Name, "/chatter");

         procedure Tick
           (Node : in out RCL.Nodes.Node'Class; Timer : in out RCL.Timers.Timer;
            Elapsed : Duration)
         is
            pragma Unreferenced (Node, Elapsed);
         begin
            Sent := Sent + 1;
            Pub.Publish_Raw (Encode ("Hello World:" & Sent'Image));
            if Sent >= Count then
               Timer.Cancel;
            end if;
         end Tick;
      begin
         Node.Timer_Add (0.1, Tick'Access);
         while Sent < Count loop
            Node.Spin (During => 0.2);
         end loop;
      end;
   end if;
end Raw_Chatter;
