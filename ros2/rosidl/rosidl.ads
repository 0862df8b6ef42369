--  ROSIDL: ROS 2 interface definitions (.msg, .srv, .action), their type
--  support, the CDR wire encoding and dynamic (by field name) messages.
--
--  This root package holds the primitive types of the ROS 2 interface
--  language, with their Ada representations, and the shared exceptions.
with Interfaces;

package ROSIDL is

   subtype Bool is Boolean;
   subtype Byte is Interfaces.Unsigned_8;
   subtype Char is Interfaces.Unsigned_8;
   --  ROS 2 "char" is an 8-bit unsigned value (rosidl maps it to uint8).
   subtype Float32 is Interfaces.IEEE_Float_32;
   subtype Float64 is Interfaces.IEEE_Float_64;
   subtype Int8 is Interfaces.Integer_8;
   subtype UInt8 is Interfaces.Unsigned_8;
   subtype Int16 is Interfaces.Integer_16;
   subtype UInt16 is Interfaces.Unsigned_16;
   subtype Int32 is Interfaces.Integer_32;
   subtype UInt32 is Interfaces.Unsigned_32;
   subtype Int64 is Interfaces.Integer_64;
   subtype UInt64 is Interfaces.Unsigned_64;

   Definition_Error : exception;
   --  A malformed interface definition; the message starts with
   --  "file:line:column: " and says what was expected.

   Unknown_Type : exception;
   --  A requested interface type is not found on the search path.

   Decode_Error : exception;
   --  Malformed CDR bytes; the message names the field path and the byte
   --  offset at which decoding failed.

   Encode_Error : exception;
   --  A message cannot be encoded (e.g. a bound is exceeded); the message
   --  names the field path.

   Field_Error : exception;
   --  A dynamic message was accessed with an unknown field name or with the
   --  wrong type; the message names the message type, the field and the
   --  valid fields.

   type GID is array (1 .. 16) of Byte;
   --  A DDS endpoint GUID (what ROS 2 calls a gid; the 24-byte rmw_gid_t
   --  of Humble holds these 16 bytes followed by zeros).

   type Message_Info is record
      Source_Timestamp   : Int64 := 0;
      --  Nanoseconds since the Unix epoch, stamped by the publisher.
      Received_Timestamp : Int64 := 0;
      --  Nanoseconds since the Unix epoch, when the sample was taken.
      Publisher_GID      : GID := [others => 0];
      --  The endpoint GUID of the publishing writer.
   end record;
   --  What a subscription callback learns about a message besides its
   --  contents (RCLAda's ROSIDL.Message_Info; written by RCL).

end ROSIDL;
