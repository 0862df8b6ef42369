--  The CDR codec working on the storage of dynamic messages (a private
--  child of ROSIDL.Dynamic; programs use ROSIDL.CDR).
with Ada.Streams;
with ROSIDL.Dynamic.CDR;

private package ROSIDL.Dynamic.Codec is

   use Ada.Streams;

   type Optional_Header (Present : Boolean := False) is record
      case Present is
         when True  => Value : CDR.Request_Header;
         when False => null;
      end case;
   end record;
   --  The request header of a service request or reply, or none (a
   --  message).

   No_Header : constant Optional_Header := (Present => False);

   function Encoded_Size
     (Msg : Message; With_Header : Boolean) return Stream_Element_Count;
   --  Also checks the bounds (Encode_Error).

   procedure Encode
     (Msg    : Message;
      Header : Optional_Header;
      Order  : CDR.Byte_Order;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset);

   procedure Decode
     (Data        : Stream_Element_Array;
      Msg         : in out Message;
      With_Header : Boolean;
      Header      : out CDR.Request_Header);
   --  Header: read when With_Header, else all zero. After a Decode_Error
   --  Msg is a valid message of unspecified contents.

   function Little_Endian_Header
     (Data : Stream_Element_Array; Type_Name : String := "") return Boolean;
   --  Decode_Error when Data has no known XCDR1 encapsulation header (its
   --  message starts with "Type_Name: " when Type_Name is given).

   function Request_Header_Of
     (Data : Stream_Element_Array; Type_Name : String) return CDR.Request_Header;
   --  The request header of a service request or reply (see
   --  CDR.Request_Header_Of).

end ROSIDL.Dynamic.Codec;
