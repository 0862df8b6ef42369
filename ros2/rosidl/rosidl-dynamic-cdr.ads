--  The CDR wire encoding of ROS 2 messages (known to programs as ROSIDL.CDR,
--  a renaming of this package): XCDR1 ("CDR_Legacy") as
--  rmw_cyclonedds_cpp writes it (see docs/ros2-wire.md):
--  a 4-byte encapsulation header (00 01 00 00 little-endian, 00 00 00 00
--  big-endian), then the fields in order, each primitive aligned to its
--  size (max 8) relative to the end of the header; strings as uint32 length
--  counting a NUL, the bytes, the NUL; wstrings as uint32 character count
--  then 4 bytes per character; fixed arrays without length; sequences with
--  a uint32 count; nested messages inline; zero-padded to a multiple of 4.
--  Example:
--     Bytes : constant Stream_Element_Array := Encode (Msg);
--     Copy  : constant Message := Decode (Support (Msg), Bytes);
--
--  Service requests and replies carry a 16-byte header (uint64 guid, int64
--  sequence, in the encapsulation's byte order) between the encapsulation
--  header and the body: use the variants with a Request_Header.
--
--  Decoding honours either byte order, never reads outside the buffer and
--  checks every length and count against the bytes that remain before
--  allocating; malformed input raises ROSIDL.Decode_Error naming the field
--  path (header.frame_id, ranges[3]: ROS 2 indices) and the byte offset
--  (from the start of the buffer). Encoding a value that violates a bound
--  raises ROSIDL.Encode_Error naming the field path.
with Ada.Streams;
with ROSIDL.Typesupport;
with System;

package ROSIDL.Dynamic.CDR is

   use Ada.Streams;

   type Byte_Order is (Big_Endian, Little_Endian);

   Native_Order : constant Byte_Order :=
     (if System."=" (System.Default_Bit_Order, System.Low_Order_First)
      then Little_Endian else Big_Endian);

   Encapsulation_Size : constant := 4;
   Request_Header_Size : constant := 16;

   type Request_Header is record
      GUID     : UInt64 := 0;
      --  The requester's writer instance handle (rmw_cyclonedds).
      Sequence : Int64 := 0;
   end record;

   function Encoded_Size
     (Msg : ROSIDL.Dynamic.Message; With_Request_Header : Boolean := False)
      return Stream_Element_Count
     with Post => Encoded_Size'Result mod 4 = 0
                  and then Encoded_Size'Result
                           >= (if With_Request_Header then 20 else 4);
   --  Bytes Encode produces (header and final padding included).

   function Encode
     (Msg : ROSIDL.Dynamic.Message; Order : Byte_Order := Native_Order)
      return Stream_Element_Array
     with Post => Encode'Result'Length = Encoded_Size (Msg)
                  and then Byte_Order_Of (Encode'Result) = Order;

   function Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Header : Request_Header;
      Order  : Byte_Order := Native_Order) return Stream_Element_Array
     with Post => Encode'Result'Length = Encoded_Size (Msg, True);

   procedure Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order);
   --  Into a caller's buffer (e.g. a DDS serdata): Buffer (Buffer'First ..
   --  Last) is the encoding (Encoded_Size (Msg) bytes). Encode_Error when
   --  Buffer is too small.

   procedure Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Header : Request_Header;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order);

   function Decode
     (Support : ROSIDL.Typesupport.Message_Support;
      Data    : Stream_Element_Array) return ROSIDL.Dynamic.Message;

   procedure Decode
     (Data : Stream_Element_Array;
      Msg  : in out ROSIDL.Dynamic.Message)
     with Pre => ROSIDL.Dynamic.Is_Initialised (Msg);
   --  Into an existing message of the right type (its storage is reused).

   procedure Decode
     (Data   : Stream_Element_Array;
      Msg    : in out ROSIDL.Dynamic.Message;
      Header : out Request_Header)
     with Pre => ROSIDL.Dynamic.Is_Initialised (Msg);
   --  A service request or reply.

   function Byte_Order_Of
     (Data : Stream_Element_Array; Type_Name : String := "") return Byte_Order;
   --  The order the encapsulation header announces; Decode_Error when the
   --  header is missing or unknown (naming Type_Name when given:
   --  "pkg/msg/Type: unknown encapsulation identifier 0, 7 ... at byte
   --  offset 0").

   function Request_Header_Of
     (Data : Stream_Element_Array; Type_Name : String) return Request_Header;
   --  The request header of a service request or reply, the body left
   --  unread: a client checks whose reply it is before decoding it.
   --  Decode_Error naming Type_Name and the byte offset when Data is cut
   --  short or its encapsulation header is unknown.
   --  Example:
   --     use type ROSIDL.UInt64;
   --     Mine  : constant ROSIDL.UInt64 := 16#1234#;
   --     Reply : constant Stream_Element_Array := Encode (Msg, (GUID => Mine, Sequence => 1));
   --     Ours  : constant Boolean := Request_Header_Of
   --       (Reply, "example_interfaces/srv/AddTwoInts_Response").GUID = Mine;

end ROSIDL.Dynamic.CDR;
