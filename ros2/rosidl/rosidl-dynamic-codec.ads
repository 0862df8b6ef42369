--  The CDR codec working on the storage of dynamic messages (a private
--  child of ROSIDL.Dynamic; programs use ROSIDL.CDR).
with Ada.Streams;

private package ROSIDL.Dynamic.Codec is

   use Ada.Streams;

   function Encoded_Size
     (Msg : Message; With_Header : Boolean) return Stream_Element_Count;
   --  Also checks the bounds (Encode_Error).

   procedure Encode
     (Msg         : Message;
      With_Header : Boolean;
      GUID        : UInt64;
      Sequence    : Int64;
      Little      : Boolean;
      Buffer      : out Stream_Element_Array;
      Last        : out Stream_Element_Offset);

   procedure Decode
     (Data        : Stream_Element_Array;
      Msg         : in out Message;
      With_Header : Boolean;
      GUID        : out UInt64;
      Sequence    : out Int64);
   --  After a Decode_Error Msg is a valid message of unspecified contents.

   function Little_Endian_Header (Data : Stream_Element_Array) return Boolean;
   --  Decode_Error when Data has no known XCDR1 encapsulation header.

end ROSIDL.Dynamic.Codec;
