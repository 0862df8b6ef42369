with Ada.Streams.Stream_IO;

package body Suite_Support is

   use Ada.Streams;
   use Ada.Streams.Stream_IO;

   function Read_All (Path : String) return Stream_Element_Array is
      F : File_Type;
   begin
      Open (F, In_File, Path);
      declare
         Data : Stream_Element_Array (1 .. Stream_Element_Offset (Size (F)));
         Last : Stream_Element_Offset;
      begin
         Read (F, Data, Last);
         Close (F);
         return Data (1 .. Last);
      end;
   end Read_All;

   procedure Write_All (Path : String; Data : Stream_Element_Array) is
      F : File_Type;
   begin
      Create (F, Out_File, Path);
      Write (F, Data);
      Close (F);
   end Write_All;

end Suite_Support;
