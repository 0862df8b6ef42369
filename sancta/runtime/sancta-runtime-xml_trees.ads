--  A read-only XML element tree that remembers where each element and each
--  attribute was in its file (XML/Ada's DOM does not keep positions, so the
--  tree is built from the SAX reader and its locations). Used by the
--  configuration loader for "file:line:column" diagnostics. Text content is
--  ignored (configurations are attributes only).
--
--     T : Tree;
--     Load ("robot.xml", T);           --  Configuration_Error when malformed
--     for Child of T.Children (T.Root) loop ... T.Name (Child) ...
with Ada.Containers.Vectors;
with Ada.Strings.Unbounded;

package Sancta.Runtime.XML_Trees is

   use Ada.Strings.Unbounded;

   type Position is record
      File   : Unbounded_String;
      Line   : Natural := 0;
      Column : Natural := 0;
   end record;

   function Image (Where : Position) return String;
   --  "file:line:column".

   type Attribute is record
      Name  : Unbounded_String;
      Value : Unbounded_String;
      Where : Position;
   end record;

   package Attribute_Vectors is new Ada.Containers.Vectors (Positive, Attribute);

   type Element_Id is new Positive;

   package Element_Vectors is new Ada.Containers.Vectors (Positive, Element_Id);

   type Tree is tagged private;

   type Load_Error is record
      Failed : Boolean := False;
      Where  : Position;
      Text   : Unbounded_String;
      --  "malformed XML: ...", "cannot open: ...", "cannot read: ...".
   end record;

   Max_Depth : constant := 100;
   --  Elements nested deeper than this are an error (bounds every recursive reader).
   Max_File_Size      : constant := 16 * 1024 * 1024;
   Max_Attribute_Size : constant := 64 * 1024;
   Max_Elements       : constant := 200_000;
   --  Limits on what Load reads (an error beyond them). A document type
   --  declaration (<!DOCTYPE ...>) is refused: no DTD, hence no entity
   --  expansion ("billion laughs") and no external entities.

   procedure Load (File : String; Result : out Tree; Error : out Load_Error);
   --  Parse File; on failure Error says where and why (Result is empty).

   procedure Load (File : String; Result : out Tree);
   --  The same, raising Configuration_Error "file:line:column: ..." on
   --  failure.

   function Root (This : Tree) return Element_Id;
   function Name (This : Tree; E : Element_Id) return String;
   function Where (This : Tree; E : Element_Id) return Position;
   function Children (This : Tree; E : Element_Id) return Element_Vectors.Vector;
   function Attributes (This : Tree; E : Element_Id) return Attribute_Vectors.Vector;

   function Has_Attribute (This : Tree; E : Element_Id; Name : String) return Boolean;
   function Attribute_Value (This : Tree; E : Element_Id; Name : String) return String;
   --  "" when absent.
   function Attribute_Where (This : Tree; E : Element_Id; Name : String) return Position;
   --  The element's position when absent.

private

   type Element is record
      Name       : Unbounded_String;
      Where      : Position;
      Attributes : Attribute_Vectors.Vector;
      Children   : Element_Vectors.Vector;
   end record;

   package Element_Stores is new Ada.Containers.Vectors (Element_Id, Element);

   type Tree is tagged record
      Elements : Element_Stores.Vector;
   end record;

end Sancta.Runtime.XML_Trees;
