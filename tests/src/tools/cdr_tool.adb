--  Drives the Ada CDR codec for the interoperability tests:
--     cdr_tool list                 the sample names
--     cdr_tool encode NAME [be]     the sample's encoding, as hex
--     cdr_tool image NAME           the sample as ros2 topic echo prints it
--     cdr_tool decode NAME HEX      decodes HEX as the sample's type and
--                                   prints its image (exit 2 and the
--                                   Decode_Error text on malformed input)
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Streams;
with Ada.Text_IO;
with ROSIDL.CDR.Samples;
with ROSIDL.Dynamic;

procedure CDR_Tool is
   use Ada.Command_Line;
   use Ada.Text_IO;
   use ROSIDL.CDR;

   procedure Usage is
   begin
      Put_Line (Standard_Error,
                "usage: cdr_tool list | encode NAME [be] | image NAME"
                & " | decode NAME HEX");
      Set_Exit_Status (Failure);
   end Usage;

begin
   if Argument_Count = 1 and then Argument (1) = "list" then
      for N of Samples.Names loop
         Put_Line (N);
      end loop;
   elsif Argument_Count in 2 .. 3 and then Argument (1) = "encode" then
      Put_Line (Samples.Hex
        (Samples.Encode_Sample
           (Argument (2),
            (if Argument_Count = 3 and then Argument (3) = "be" then Big_Endian
             else Little_Endian))));
   elsif Argument_Count = 2 and then Argument (1) = "image" then
      Put (ROSIDL.Dynamic.Image (Samples.Make (Argument (2))));
   elsif Argument_Count = 3 and then Argument (1) = "decode" then
      declare
         Msg  : ROSIDL.Dynamic.Message := Samples.Make (Argument (2));
         Data : constant Ada.Streams.Stream_Element_Array :=
           Samples.From_Hex (Argument (3));
         Header : Request_Header;
      begin
         if Samples.Is_Request (Argument (2)) then
            Decode (Data, Msg, Header);
            Put_Line ("# guid" & Header.GUID'Image & " seq" & Header.Sequence'Image);
         else
            Decode (Data, Msg);
         end if;
         Put (ROSIDL.Dynamic.Image (Msg));
      exception
         when E : ROSIDL.Decode_Error =>
            Put_Line (Standard_Error, "Decode_Error: "
                      & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (2);
      end;
   else
      Usage;
   end if;
end CDR_Tool;
