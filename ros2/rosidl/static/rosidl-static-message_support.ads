--  What every generated message package instantiates as Handling: the
--  type's names and hash, and its complete CDR encoding (encapsulation
--  header, optional service request header, final padding) around the
--  generated body codec. The typed publishers, subscriptions, services and
--  clients of RCL take an instance (as RCLAda's ROSIDL.Static.Message_Support):
--  Example:
--     package Twist renames ROSIDL.Static.Geometry_Msgs.Messages.Twist;
--     Bytes : constant Stream_Element_Array := Twist.Handling.Encode (Cmd);
--     Copy  : constant Twist.Message := Twist.Handling.Decode (Bytes);
--
--  Encoding and decoding follow ROSIDL.CDR byte for byte: decoding honours
--  either byte order, never reads outside Data and raises Decode_Error
--  naming the type, the field and the byte offset of malformed input.
pragma Warnings (Off, "formal object * is not referenced");
--  DDS_Type_Name, Type_Hash, Is_Bounded: for the users of an instance.
with Ada.Streams;
with ROSIDL.CDR;
with ROSIDL.Static.Impl.Wire;

generic
   type Message is private;
   Full_Name : String;
   --  "std_msgs/msg/String"
   DDS_Type_Name : String;
   --  "std_msgs::msg::dds_::String_"
   Type_Hash : String;
   --  REP 2011 ("RIHS01_..."), as ROSIDL.Type_Hashes computes it.
   Is_Bounded : Boolean;
   --  No unbounded string or sequence anywhere in the type: a message
   --  lives entirely in its record (no heap).
   with procedure Size_Body (Msg : Message; Pos : in out Ada.Streams.Stream_Element_Offset);
   with procedure Write_Body
     (Msg : Message;
      B   : in out Ada.Streams.Stream_Element_Array;
      C   : in out ROSIDL.Static.Impl.Wire.Cursor);
   with procedure Read_Body
     (B   : Ada.Streams.Stream_Element_Array;
      C   : in out ROSIDL.Static.Impl.Wire.Cursor;
      Msg : in out Message);
   with function "=" (Left, Right : Message) return Boolean is <>;
package ROSIDL.Static.Message_Support is

   use Ada.Streams;
   use ROSIDL.CDR;

   function Encoded_Size
     (Msg : Message; With_Request_Header : Boolean := False) return Stream_Element_Count
     with Post => Encoded_Size'Result mod 4 = 0;

   procedure Encode
     (Msg    : Message;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order);
   --  Into Buffer (Buffer'First .. Last), in one pass (no size pass): a
   --  publisher that sized its buffer with Encoded_Size pays for that
   --  pass once. Encode_Error when Buffer is too small, after writing at
   --  most up to Buffer'Last.

   procedure Encode
     (Msg    : Message;
      Header : Request_Header;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order);
   --  A service request or reply.

   function Encode (Msg : Message; Order : Byte_Order := Native_Order)
      return Stream_Element_Array
     with Post => Encode'Result'Length = Encoded_Size (Msg);

   procedure Decode (Data : Stream_Element_Array; Msg : in out Message);
   --  Into Msg, whose storage (sequences, strings) is reused.

   procedure Decode
     (Data   : Stream_Element_Array;
      Msg    : in out Message;
      Header : out Request_Header);

   function Decode (Data : Stream_Element_Array) return Message;

   --  For tests: what the generated codec makes of bytes that another
   --  encoder (the dynamic codec) wrote.
   function Recode (Data : Stream_Element_Array; Order : Byte_Order)
      return Stream_Element_Array;
   --  Encode (Decode (Data), Order).
   procedure Recode_Into
     (Data   : Stream_Element_Array;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order);
   --  Encode (Decode (Data), Buffer, Last, Order).
   function Round_Trips (Data : Stream_Element_Array) return Boolean;
   --  Decode (Encode (X)) = X for X = Decode (Data), in both byte orders.
   function Encode_Default return Stream_Element_Array;
   --  A message of default values (the definition's, else zeros and empty
   --  texts and sequences), little-endian.

end ROSIDL.Static.Message_Support;
