--  Validation and normalisation of the literal values of the
--  interface language (constants and default values), as ROS 2 accepts them.
--  Pure functions: a problem is reported in the result, never raised.
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;

private package ROSIDL.Parser.Literals is

   use Ada.Strings.Unbounded;

   type Check_Result is record
      OK       : Boolean := False;
      Value    : Unbounded_String;
      --  The normalised value when OK (see Field.Default).
      Expected : Unbounded_String;
      --  When not OK: what was expected ("an int8 value in -128 .. 127").
   end record;

   function Check_Scalar
     (Kind         : Element_Kind;
      String_Bound : Natural;
      Text         : String) return Check_Result
     with Pre => Kind /= Message_Kind;
   --  Text (already trimmed) as one value of Kind: integers (decimal, or
   --  0x / 0o / 0b prefixed, with an optional sign) in the range of Kind,
   --  floats (Python syntax, inf and nan included), booleans (true / false
   --  / 1 / 0, any case), strings (quoted with ' or ", or unquoted) within
   --  String_Bound characters when it is not 0.

   type Element_Span is record
      First, Last : Natural := 0;
      --  The element's text in the array literal (Last < First when empty).
   end record;

   package Span_Vectors is new Ada.Containers.Vectors (Positive, Element_Span);

   type Split_Result is record
      OK       : Boolean := False;
      Elements : Span_Vectors.Vector;
      Expected : Unbounded_String;
      Where    : Natural := 0;
      --  When not OK: index in the text where the problem is.
   end record;

   function Split_Array (Text : String; Quoted : Boolean) return Split_Result;
   --  Splits an array literal "[a, b, c]" into its elements (trimmed).
   --  Quoted: the elements are strings, whose quotes may hold commas.

   function Trim_Blanks (S : String) return String;
   --  S without leading and trailing spaces and tabs.

   function Is_Blank (C : Character) return Boolean is (C = ' ' or else C = ASCII.HT);

end ROSIDL.Parser.Literals;
