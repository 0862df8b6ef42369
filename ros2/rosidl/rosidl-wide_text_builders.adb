package body ROSIDL.Wide_Text_Builders is

   procedure Append (This : in out Builder; Item : Wide_Wide_Character) is
   begin
      if This.Used = This.Chunk'Last then
         Append (This.Text, This.Chunk);
         This.Used := 0;
      end if;
      This.Used := This.Used + 1;
      This.Chunk (This.Used) := Item;
   end Append;

   procedure Take (This : in out Builder; Text : out Unbounded_Wide_Wide_String) is
   begin
      Append (This.Text, This.Chunk (1 .. This.Used));
      Text := This.Text;
      This.Text := Null_Unbounded_Wide_Wide_String;
      This.Used := 0;
   end Take;

end ROSIDL.Wide_Text_Builders;
