--  A wide text built character by character, as the CDR decoders read a
--  wstring: 256 characters at a time, so that a long wstring neither sits
--  on the stack nor grows its text by one character at a time.
with Ada.Strings.Wide_Wide_Unbounded;

private package ROSIDL.Wide_Text_Builders is

   use Ada.Strings.Wide_Wide_Unbounded;

   type Builder is limited private;

   procedure Append (This : in out Builder; Item : Wide_Wide_Character);

   procedure Take (This : in out Builder; Text : out Unbounded_Wide_Wide_String);
   --  Text: what was appended since the last Take; This starts over empty.

private

   type Builder is limited record
      Chunk : Wide_Wide_String (1 .. 256);
      Used  : Natural := 0;
      --  Chunk (1 .. Used) follows Text.
      Text  : Unbounded_Wide_Wide_String;
   end record;

end ROSIDL.Wide_Text_Builders;
