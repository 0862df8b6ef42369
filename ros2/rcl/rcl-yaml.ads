--  A small YAML reader for what ROS 2 users write: parameter files
--  ("node: ros__parameters: ..."), the values of "--ros-args -p name:=value"
--  and the messages of "rclada topic pub" / "service call" ("{a: 1, b: 2}").
--
--  Supported: block mappings and sequences (indentation by spaces, "- "
--  items, compact "- key: value" items), flow sequences "[a, b]" and flow
--  mappings "{a: 1}" (nested, spanning lines), plain, 'single' and "double"
--  quoted scalars (with \n \t \" \\ \uXXXX escapes), comments, "---" at the
--  start. Not supported (a Parse_Error says so): anchors and aliases, tags,
--  block scalars (| and >), multi-line plain scalars, complex keys, several
--  documents.
--
--  Every error names the place: "params.yaml:3:7: ...".
--  Example:
--     D : constant Document := Parse ("{a: 2, b: [1, 2.5, 'x']}");
--     pragma Assert (D.Kind (D.Root) = Mapping and D.Text (D.Find (D.Root, "a")) = "2");
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;

package RCL.YAML is

   Parse_Error : exception;
   --  Message: "<source>:<line>:<column>: <what>".

   type Node_Kind is (Null_Value, Scalar, Sequence, Mapping);

   type Scalar_Kind is (Null_Scalar, Bool_Scalar, Int_Scalar, Float_Scalar, String_Scalar);
   --  The YAML 1.2 core schema resolution of a plain scalar (also True /
   --  False / TRUE / FALSE); quoted scalars are strings.

   type Document is tagged private;

   subtype Node is Positive;

   Max_Depth : constant := 100;
   --  Documents nested deeper than this (each collection and each block value counts
   --  one level) are a Parse_Error: bounds the recursion of the parser and of every
   --  reader of a Document, whatever the input.

   function Parse (Text : String; Source : String := "<input>") return Document;
   --  An empty text (or only comments) gives a Null_Value root.

   function Parse_File (Path : String) return Document;
   --  Parse_Error naming Path when it cannot be read. Messages and
   --  locations quote a Path of over 80 characters with its middle left
   --  out ("/tmp/very/long/...path/params.yaml:3:7: ..."): the reason stays
   --  within GNAT's 200 characters of exception message.

   function Root (This : Document) return Node;
   function Kind (This : Document; N : Node) return Node_Kind;
   function Text (This : Document; N : Node) return String;
   --  A scalar's value (escapes resolved, quotes removed); "" otherwise.
   function Quoted (This : Document; N : Node) return Boolean;
   function Scalar_Type (This : Document; N : Node) return Scalar_Kind
     with Pre => Kind (This, N) in Scalar | Null_Value;
   function Length (This : Document; N : Node) return Natural;
   --  Items of a sequence, pairs of a mapping, 0 otherwise.
   function Item (This : Document; N : Node; I : Positive) return Node
     with Pre => I <= Length (This, N);
   --  The I-th item, or the value of the I-th pair.
   function Key (This : Document; N : Node; I : Positive) return String
     with Pre => Kind (This, N) = Mapping and then I <= Length (This, N);
   function Key_Where (This : Document; N : Node; I : Positive) return String
     with Pre => Kind (This, N) = Mapping and then I <= Length (This, N);
   --  "<source>:<line>:<column>" of the I-th key.
   function Find (This : Document; N : Node; Key : String) return Natural;
   --  The value node of Key in mapping N, 0 when absent.
   function Where (This : Document; N : Node) return String;
   --  "<source>:<line>:<column>" of N.

   function Classify (Text : String) return Scalar_Kind;
   --  The resolution of a plain scalar Text.

   function Integer_Value (Text : String) return Long_Long_Integer;
   function Float_Value (Text : String) return Long_Float;
   --  The value of an Int_Scalar (decimal, 0x hex, 0o octal) / a
   --  Float_Scalar or Int_Scalar (".inf", ".nan" included); Constraint_Error
   --  when Text is not of that kind or out of range.

   function Image (This : Document; N : Node) return String;
   --  N in flow style ("{a: 1, b: [x, 'y z']}"), for messages and tests.

private

   use Ada.Strings.Unbounded;

   package Index_Vectors is new Ada.Containers.Vectors (Positive, Positive);
   package Key_Vectors is new Ada.Containers.Vectors (Positive, Unbounded_String);

   type Position is record
      Line, Column : Positive;
   end record;

   package Position_Vectors is new Ada.Containers.Vectors (Positive, Position);

   type Node_Record is record
      Kind     : Node_Kind := Null_Value;
      Text     : Unbounded_String;
      Quoted   : Boolean := False;
      Line     : Positive := 1;
      Column   : Positive := 1;
      Children : Index_Vectors.Vector;
      Keys     : Key_Vectors.Vector;
      Key_At   : Position_Vectors.Vector;
   end record;

   package Node_Vectors is new Ada.Containers.Vectors (Positive, Node_Record);

   type Document is tagged record
      Nodes  : Node_Vectors.Vector;
      Root   : Positive := 1;
      Source : Unbounded_String;
   end record;

end RCL.YAML;
