with ROSIDL.Dynamic.Codec;

package body ROSIDL.Dynamic.CDR is

   function Encoded_Size
     (Msg : ROSIDL.Dynamic.Message; With_Request_Header : Boolean := False)
      return Stream_Element_Count is
     (Codec.Encoded_Size (Msg, With_Request_Header));

   function Encode
     (Msg : ROSIDL.Dynamic.Message; Order : Byte_Order := Native_Order)
      return Stream_Element_Array
   is
      Result : Stream_Element_Array (1 .. Encoded_Size (Msg));
      Last   : Stream_Element_Offset;
   begin
      Codec.Encode (Msg, Codec.No_Header, Order, Result, Last);
      return Result;
   end Encode;

   function Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Header : Request_Header;
      Order  : Byte_Order := Native_Order) return Stream_Element_Array
   is
      Result : Stream_Element_Array (1 .. Encoded_Size (Msg, True));
      Last   : Stream_Element_Offset;
   begin
      Codec.Encode (Msg, (Present => True, Value => Header), Order, Result, Last);
      return Result;
   end Encode;

   procedure Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order) is
   begin
      Codec.Encode (Msg, Codec.No_Header, Order, Buffer, Last);
   end Encode;

   procedure Encode
     (Msg    : ROSIDL.Dynamic.Message;
      Header : Request_Header;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order) is
   begin
      Codec.Encode (Msg, (Present => True, Value => Header), Order, Buffer, Last);
   end Encode;

   function Decode
     (Support : ROSIDL.Typesupport.Message_Support;
      Data    : Stream_Element_Array) return ROSIDL.Dynamic.Message is
   begin
      return Msg : ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support) do
         Decode (Data, Msg);
      end return;
   end Decode;

   procedure Decode
     (Data : Stream_Element_Array;
      Msg  : in out ROSIDL.Dynamic.Message)
   is
      Ignored : Request_Header;
   begin
      Codec.Decode (Data, Msg, False, Ignored);
   end Decode;

   procedure Decode
     (Data   : Stream_Element_Array;
      Msg    : in out ROSIDL.Dynamic.Message;
      Header : out Request_Header) is
   begin
      Codec.Decode (Data, Msg, True, Header);
   end Decode;

   function Byte_Order_Of
     (Data : Stream_Element_Array; Type_Name : String := "") return Byte_Order is
     (if Codec.Little_Endian_Header (Data, Type_Name) then Little_Endian else Big_Endian);

   function Request_Header_Of
     (Data : Stream_Element_Array; Type_Name : String) return Request_Header is
     (Codec.Request_Header_Of (Data, Type_Name));

end ROSIDL.Dynamic.CDR;
