--  Dynamic messages: any ROS 2 message accessed by field name, in the style
--  of RCLAda. A Message is a value (copying it copies its contents) that
--  knows its type support; fields are reached by indexing with their name
--  and yield references into the message (no copy):
--  Example:
--     Msg : constant Message :=
--       Init (Get_Message_Support ("sensor_msgs", "LaserScan"));
--     Msg ("angle_min").As_Float32 := -1.57;
--     Msg ("header")("frame_id").Set_String ("laser");
--     Msg ("header").Get_Message ("stamp")("sec").As_Int32 := 12;
--     Msg ("ranges").As_Array.Resize (720);
--     Msg ("ranges").As_Array (42).As_Float32 := 1.5;
--     Msg ("ranges").Set_Float32_Array (Scan);       --  bulk, one copy
--     Put_Line (Image (Msg));                         --  as ros2 topic echo
--
--  Array indices are 1-based (Ada convention): element I of the API is
--  element I - 1 of ROS 2 (error messages and Image use the ROS 2 index).
--  Every access is checked: an unknown field name or an accessor of the
--  wrong type raises ROSIDL.Field_Error naming the message type, the field,
--  the valid fields and the expected and requested types; an index out of
--  bounds, resizing a fixed array or a bounded sequence beyond its bound
--  also raise Field_Error.
--
--  Primitive arrays and sequences are stored compactly (one contiguous
--  buffer in native layout) so that bulk access and the CDR codec are block
--  copies. Copies of a message share its storage until one of them hands
--  out a reference, so returning or passing messages costs no copy.
--  References (Field_Ref, Array_Ref, the As_* results) stay valid as long
--  as the message is neither finalised nor the enclosing sequence resized,
--  as with the standard containers. Several tasks may read one message
--  object at once (indexing included); writing it, or copying it while
--  another task writes it, needs the caller's synchronisation.
with Ada.Finalization;
with Ada.Strings.Unbounded;
with Ada.Strings.Wide_Wide_Unbounded;
with Ada.Containers.Vectors;
with ROSIDL.Definitions;
with ROSIDL.Typesupport;
with System;
with System.Atomic_Counters;

package ROSIDL.Dynamic is

   use ROSIDL.Definitions;
   use ROSIDL.Typesupport;

   type Message is tagged private
     with Constant_Indexing => Reference;
   --  A message of one type. The default value is not initialised (every
   --  access raises Field_Error); obtain messages through Init.
   --  (GNAT 12 ignores the indexing aspects where the full view is visible,
   --  i.e. in children of this package: call Reference there.)

   function Init (Support : Message_Support) return Message
     with Post => Is_Initialised (Init'Result);
   --  A message whose fields have their default values: the definition's
   --  defaults when given, else zero, False, empty strings; sequences empty
   --  (or the default list), fixed arrays sized.

   function Is_Initialised (This : Message) return Boolean;

   function Support (This : Message) return Message_Support
     with Pre => Is_Initialised (This);

   function Definition (This : Message) return Message_Access
     with Pre => Is_Initialised (This);

   function Type_Name (This : Message) return String;
   --  "std_msgs/msg/String", or "(uninitialised message)".

   overriding function "=" (Left, Right : Message) return Boolean;
   --  Same type and same contents (floats compared bit for bit).

   -------------------------------------------------------------------
   -- Field references --
   -------------------------------------------------------------------

   type Field_Ref is tagged private
     with Constant_Indexing => Field_Reference;
   --  One value of a field: the field itself (a single value, an array or
   --  a sequence as a whole), or one element of an array or sequence.
   --  Indexing a reference to a nested message by a field name gives that
   --  field: Msg ("header")("stamp").

   function Reference (This : Message'Class; Name : String) return Field_Ref;
   --  The named field; raises Field_Error when there is none. The result
   --  designates the storage of This (no copy): assigning through it
   --  changes This, even when This is a constant (as in RCLAda).

   function Field_Reference (This : Field_Ref; Name : String) return Field_Ref;
   function Get_Message (This : Field_Ref; Name : String) return Field_Ref
     renames Field_Reference;
   --  The named field of the nested message This designates.

   function Name (This : Field_Ref) return String;
   --  The field name, with "[I]" (ROS 2 index) for an array element.

   function Field_Type_Of (This : Field_Ref) return Field_Type;
   --  The declared type of the field.

   function Is_Collection (This : Field_Ref) return Boolean;
   --  True when This designates a whole array or sequence.

   --  Scalar references: "Msg ("x").As_Float32 := 1.0;"

   type Bool_Ref (Element : not null access Bool) is null record
     with Implicit_Dereference => Element;
   type UInt8_Ref (Element : not null access UInt8) is null record
     with Implicit_Dereference => Element;
   --  Also for byte and char.
   type Int8_Ref (Element : not null access Int8) is null record
     with Implicit_Dereference => Element;
   type Int16_Ref (Element : not null access Int16) is null record
     with Implicit_Dereference => Element;
   type UInt16_Ref (Element : not null access UInt16) is null record
     with Implicit_Dereference => Element;
   type Int32_Ref (Element : not null access Int32) is null record
     with Implicit_Dereference => Element;
   type UInt32_Ref (Element : not null access UInt32) is null record
     with Implicit_Dereference => Element;
   type Int64_Ref (Element : not null access Int64) is null record
     with Implicit_Dereference => Element;
   type UInt64_Ref (Element : not null access UInt64) is null record
     with Implicit_Dereference => Element;
   type Float32_Ref (Element : not null access Float32) is null record
     with Implicit_Dereference => Element;
   type Float64_Ref (Element : not null access Float64) is null record
     with Implicit_Dereference => Element;

   function As_Bool (This : Field_Ref) return Bool_Ref;
   function As_Byte (This : Field_Ref) return UInt8_Ref;
   function As_Char (This : Field_Ref) return UInt8_Ref;
   function As_UInt8 (This : Field_Ref) return UInt8_Ref;
   function As_Int8 (This : Field_Ref) return Int8_Ref;
   function As_Int16 (This : Field_Ref) return Int16_Ref;
   function As_UInt16 (This : Field_Ref) return UInt16_Ref;
   function As_Int32 (This : Field_Ref) return Int32_Ref;
   function As_UInt32 (This : Field_Ref) return UInt32_Ref;
   function As_Int64 (This : Field_Ref) return Int64_Ref;
   function As_UInt64 (This : Field_Ref) return UInt64_Ref;
   function As_Float32 (This : Field_Ref) return Float32_Ref;
   function As_Float64 (This : Field_Ref) return Float64_Ref;
   --  The single value This designates; Field_Error when the field's
   --  element type is not the one requested or This is a whole array.
   --  Builds with validity checks (-gnatVa, the debug build) raise
   --  Constraint_Error on reading a NaN float: test Is_NaN first.

   function Is_NaN (This : Field_Ref) return Boolean;
   --  The float32 / float64 value This designates is a NaN (read without
   --  reading it as a float). Field_Error for other types.

   procedure Set_String (This : Field_Ref; Value : String);
   function Get_String (This : Field_Ref) return String;
   procedure Set_WString (This : Field_Ref; Value : Wide_Wide_String);
   function Get_WString (This : Field_Ref) return Wide_Wide_String;
   --  string and wstring values. A bounded string may hold more than its
   --  bound; encoding it then raises Encode_Error.

   function To_Message (This : Field_Ref'Class) return Message;
   --  A copy of the nested message This designates.

   procedure Set_Message (This : Field_Ref; Value : Message'Class);
   --  Replaces the nested message This designates by a copy of Value (of
   --  the same type, else Field_Error).

   -------------------------------------------------------------------
   -- Arrays and sequences --
   -------------------------------------------------------------------

   type Array_Ref is tagged private
     with Constant_Indexing => Element;
   --  A fixed array, bounded or unbounded sequence field.

   function As_Array (This : Field_Ref'Class) return Array_Ref;
   --  Field_Error when the field is not an array or sequence.

   function As_Array (This : Field_Ref'Class; Index : Positive) return Field_Ref;
   --  Element (As_Array (This), Index): "Msg ("ranges").As_Array (42)".
   --  (GNAT does not resolve a prefixed call followed by an indexing, so
   --  this overload provides the RCLAda notation.)

   function Length (This : Array_Ref) return Natural;

   function Capacity (This : Array_Ref) return Natural;
   --  N for T[N] and T[<=N]; Natural'Last for T[].

   procedure Resize (This : Array_Ref; Length : Natural)
     with Post => ROSIDL.Dynamic.Length (This) = Length;
   --  New elements take their type's zero/default value. Field_Error for
   --  a fixed array (unless Length is its size) or beyond a bound.

   function Element (This : Array_Ref'Class; Index : Positive) return Field_Ref;
   --  Element Index (1 .. Length); Field_Error when out of range.

   type Index_Array is array (Positive range <>) of Positive;

   function As_Matrix (This : Field_Ref; Indices : Index_Array) return Field_Ref;
   function As_Matrix
     (This : Message'Class; Indices : Index_Array) return Field_Ref;
   --  For a std_msgs/*MultiArray (the message, or a field holding one):
   --  the element of "data" at Indices (1-based, one per layout dimension),
   --  at data_offset + sum ((Indices (K) - 1) * dim[K + 1].stride) +
   --  Indices (Last) - 1 (ROS 2 row-major layout). Field_Error when an
   --  index exceeds its dimension's size, the index count differs from the
   --  dimension count or the element is beyond data.

   --  Bulk access to primitive arrays and sequences (one block copy):

   type Bool_Array is array (Positive range <>) of Bool;
   type UInt8_Array is array (Positive range <>) of UInt8;
   type Int8_Array is array (Positive range <>) of Int8;
   type Int16_Array is array (Positive range <>) of Int16;
   type UInt16_Array is array (Positive range <>) of UInt16;
   type Int32_Array is array (Positive range <>) of Int32;
   type UInt32_Array is array (Positive range <>) of UInt32;
   type Int64_Array is array (Positive range <>) of Int64;
   type UInt64_Array is array (Positive range <>) of UInt64;
   type Float32_Array is array (Positive range <>) of Float32;
   type Float64_Array is array (Positive range <>) of Float64;

   procedure Set_Bool_Array (This : Field_Ref; Values : Bool_Array);
   procedure Set_UInt8_Array (This : Field_Ref; Values : UInt8_Array);
   --  For uint8, byte and char arrays.
   procedure Set_Int8_Array (This : Field_Ref; Values : Int8_Array);
   procedure Set_Int16_Array (This : Field_Ref; Values : Int16_Array);
   procedure Set_UInt16_Array (This : Field_Ref; Values : UInt16_Array);
   procedure Set_Int32_Array (This : Field_Ref; Values : Int32_Array);
   procedure Set_UInt32_Array (This : Field_Ref; Values : UInt32_Array);
   procedure Set_Int64_Array (This : Field_Ref; Values : Int64_Array);
   procedure Set_UInt64_Array (This : Field_Ref; Values : UInt64_Array);
   procedure Set_Float32_Array (This : Field_Ref; Values : Float32_Array);
   procedure Set_Float64_Array (This : Field_Ref; Values : Float64_Array);
   --  Replaces the whole array / sequence (resizing a sequence; a fixed
   --  array needs exactly its size; a bounded sequence at most its bound).

   function Get_Bool_Array (This : Field_Ref) return Bool_Array;
   function Get_UInt8_Array (This : Field_Ref) return UInt8_Array;
   function Get_Int8_Array (This : Field_Ref) return Int8_Array;
   function Get_Int16_Array (This : Field_Ref) return Int16_Array;
   function Get_UInt16_Array (This : Field_Ref) return UInt16_Array;
   function Get_Int32_Array (This : Field_Ref) return Int32_Array;
   function Get_UInt32_Array (This : Field_Ref) return UInt32_Array;
   function Get_Int64_Array (This : Field_Ref) return Int64_Array;
   function Get_UInt64_Array (This : Field_Ref) return UInt64_Array;
   function Get_Float32_Array (This : Field_Ref) return Float32_Array;
   function Get_Float64_Array (This : Field_Ref) return Float64_Array;

   -------------------------------------------------------------------
   -- Constants and rendering --
   -------------------------------------------------------------------

   function Constant_Value (This : Message; Name : String) return String;
   --  A constant of the message's definition, as normalised by the parser
   --  ("5", "0.5", "true", "text"); Field_Error naming the valid constants
   --  when there is none of that name.

   function Constant_Int64 (This : Message; Name : String) return Int64;
   function Constant_Float64 (This : Message; Name : String) return Float64;
   --  Field_Error for a nan or an infinite constant (Constant_Value gives
   --  "nan", "inf", "-inf"): such values do not pass validity checks.
   function Constant_WString (This : Message; Name : String) return Wide_Wide_String;
   --  A (w)string constant's text decoded from UTF-8; Field_Error when it
   --  is not valid UTF-8.

   function Image (This : Message; Truncate_Length : Natural := 0) return String;
   --  YAML as "ros2 topic echo" prints it (without the "---" separator),
   --  one "field: value" per line, nested messages indented by 2, arrays as
   --  "- item" lists ("[]" when empty). Truncate_Length > 0 shortens
   --  arrays and strings longer than it as ros2 topic echo does with "...".

private

   use Ada.Strings.Unbounded;
   use Ada.Strings.Wide_Wide_Unbounded;

   type Node;
   type Node_Access is access Node;

   type Word_Array is array (Natural range <>) of UInt64;
   type Word_Access is access Word_Array;
   --  Primitive storage: 8-byte aligned, elements packed in native layout.

   package Text_Vectors is new Ada.Containers.Vectors
     (Positive, Unbounded_String);
   package Wide_Text_Vectors is new Ada.Containers.Vectors
     (Positive, Unbounded_Wide_Wide_String);
   package Node_Vectors is new Ada.Containers.Vectors (Positive, Node_Access);

   type Cell_Extra is record
      Texts  : Text_Vectors.Vector;
      WTexts : Wide_Text_Vectors.Vector;
      Nodes  : Node_Vectors.Vector;
   end record;
   --  The storage of string, wstring and message fields (only theirs).

   type Extra_Access is access Cell_Extra;

   type Field_Cell is limited record
      Owner  : Node_Access;
      --  The message holding this field.
      Field  : Positive := 1;
      --  Its index in Owner.Def.Fields.
      Of_Type : Field_Type;
      --  Owner.Def.Fields (Field).Of_Type, cached.
      Count  : Natural := 0;
      --  Number of elements (1 for a single value).
      Prims  : Word_Access;
      --  Primitive elements (Count * size bytes used).
      Extra  : Extra_Access;
      --  Elements of the other kinds (null for a primitive field).
   end record;

   type Cell_Array is array (Positive range <>) of aliased Field_Cell;

   type Node (Field_Count : Positive) is limited record
      Def        : Message_Access;
      Shares     : System.Atomic_Counters.Atomic_Counter;
      --  Messages sharing this root (1 when unshared); unused elsewhere.
      Referenced : Boolean := False;
      --  A reference into this root was handed out: copies must be deep.
      Cells      : Cell_Array (1 .. Field_Count);
   end record;

   type Message is new Ada.Finalization.Controlled with record
      Root : Node_Access;
   end record;
   --  Copies share their root until one of them hands out a reference
   --  (Reference, As_Matrix) or is decoded into: then it takes a private
   --  deep copy first. A root that has handed out references is always
   --  deep-copied. So function results (Decode, Init) are not copied, and
   --  writes through references never show in another message.

   procedure Make_Unique
     (This : Message'Class; Referenced : Boolean; Keep_Contents : Boolean := True);
   --  Gives This a root of its own (a deep copy when shared, or a message
   --  of default values unless Keep_Contents); Referenced marks it as
   --  having handed out references.

   overriding procedure Adjust (This : in out Message);
   overriding procedure Finalize (This : in out Message);

   type Cell_Access is access all Field_Cell;

   type Field_Ref is tagged record
      Cell  : Cell_Access;
      Index : Natural := 0;
      --  0: the whole field; else the element (1-based).
   end record;

   type Array_Ref is tagged record
      Cell : Cell_Access;
   end record;

   --  Shared with the CDR codec (ROSIDL.Dynamic.Codec).

   function New_Node (Def : not null Message_Access) return Node_Access;
   --  A message tree with default values.

   procedure Free (N : in out Node_Access);

   function Element_Address
     (Cell : Field_Cell; Index : Positive) return System.Address;

   procedure Set_Count (Cell : in out Field_Cell; Count : Natural);
   --  Resizes the storage of Cell (any element kind), new elements get
   --  their default values (zero for primitives).

   function Cell_Type (Cell : Field_Cell) return Field_Type is (Cell.Of_Type);

end ROSIDL.Dynamic;
