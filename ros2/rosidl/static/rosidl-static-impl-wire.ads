--  For generated code (ROSIDL.Static.Impl): the XCDR1 primitives the
--  generated codecs call (the rules of ROSIDL.CDR: each primitive aligned
--  to its size relative to the end of the encapsulation header, strings as
--  a uint32 length counting a NUL, sequences with a uint32 count). Reading
--  checks every length and count against the bytes that remain and raises
--  ROSIDL.Decode_Error naming the field and the byte offset, never reading
--  outside the buffer. Writing makes no size pass: every store is
--  index-checked (the checks are kept on in the bodies), so a buffer too
--  small raises Constraint_Error at its end, never writes past it
--  (Message_Support reports it as Encode_Error).
with Ada.Streams;
with Ada.Strings.Unbounded;
with Ada.Strings.Wide_Wide_Unbounded;

package ROSIDL.Static.Impl.Wire is

   use Ada.Streams;

   type Cursor is record
      Pos    : Stream_Element_Offset := 0;
      --  Buffer index of the next byte.
      Origin : Stream_Element_Offset := 0;
      --  Buffer index of CDR offset 0 (the end of the encapsulation header).
      Swap   : Boolean := False;
      --  The wire's byte order is not the machine's.
   end record;

   --  Size pass: Pos is relative to the origin -----------------------------

   procedure Add (Pos : in out Stream_Element_Offset; Align, Bytes : Stream_Element_Offset)
     with Inline;
   --  Aligns Pos to Align, then advances it by Bytes.

   procedure Add_String (Pos : in out Stream_Element_Offset; Length : Natural) with Inline;
   procedure Add_WString (Pos : in out Stream_Element_Offset; Length : Natural) with Inline;

   --  Writing ---------------------------------------------------------------

   procedure Pad (B : in out Stream_Element_Array; C : in out Cursor;
                  Align : Stream_Element_Offset) with Inline;
   --  Zero bytes up to the next multiple of Align.

   procedure Put_Count (B : in out Stream_Element_Array; C : in out Cursor; Count : Natural);
   procedure Put_String (B : in out Stream_Element_Array; C : in out Cursor; Text : String);
   procedure Put_String
     (B    : in out Stream_Element_Array;
      C    : in out Cursor;
      Text : Ada.Strings.Unbounded.Unbounded_String);
   --  The same without copying Text to a String first.
   procedure Put_WString
     (B : in out Stream_Element_Array; C : in out Cursor; Text : Wide_Wide_String);

   procedure Put_Request_Header
     (B : in out Stream_Element_Array; C : in out Cursor; GUID : UInt64; Sequence : Int64);
   --  The 16-byte header of service requests and replies.

   --  Reading ---------------------------------------------------------------

   procedure Fail (B : Stream_Element_Array; At_Pos : Stream_Element_Offset; What, Problem : String)
     with No_Return;
   --  Raises Decode_Error "What: Problem at byte offset N" (N from the start
   --  of B).

   function Remaining (B : Stream_Element_Array; C : Cursor) return Long_Long_Integer is
     (Long_Long_Integer (B'Last) - Long_Long_Integer (C.Pos) + 1);

   procedure Skip_Pad (C : in out Cursor; Align : Stream_Element_Offset) with Inline;

   function Get_Count
     (B        : Stream_Element_Array;
      C        : in out Cursor;
      Min_Size : Positive;
      Bound    : Natural;
      What     : String) return Natural;
   --  A sequence count: at most Bound (when not 0) and no more elements of
   --  at least Min_Size bytes than the bytes that remain.

   type String_Span is record
      First  : Stream_Element_Offset;
      Length : Natural;
   end record;
   --  A string's characters in a buffer B: B (First .. First + Length - 1).

   function Get_String_Span
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      What  : String) return String_Span;
   --  A string, left in B.

   function Text (B : Stream_Element_Array; Span : String_Span) return String;

   procedure Get_String
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      Into  : in out Ada.Strings.Unbounded.Unbounded_String;
      What  : String);
   --  Into's storage is reused when large enough.

   function Get_WString
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      What  : String) return Wide_Wide_String;

   procedure Get_WString
     (B     : Stream_Element_Array;
      C     : in out Cursor;
      Bound : Natural;
      Into  : out Ada.Strings.Wide_Wide_Unbounded.Unbounded_Wide_Wide_String;
      What  : String);

end ROSIDL.Static.Impl.Wire;
