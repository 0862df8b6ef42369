pragma Validity_Checks (Off);
--  Floats may be NaN or infinite (ROS 2 data, definitions).
package body ROSIDL.Static.Message_Support is

   pragma Unsuppress (Index_Check);
   pragma Unsuppress (Length_Check);
   --  Write relies on them (as ROSIDL.Static.Impl.Wire does).

   Header_Size : constant := ROSIDL.CDR.Request_Header_Size;

   function Encoded_Size
     (Msg : Message; With_Request_Header : Boolean := False) return Stream_Element_Count
   is
      Pos : Stream_Element_Offset := (if With_Request_Header then Header_Size else 0);
   begin
      Size_Body (Msg, Pos);
      return Encapsulation_Size + Pos + (-Pos) mod 4;
   end Encoded_Size;

   procedure Put_Header (Buffer : out Stream_Element_Array; Order : Byte_Order) is
   begin
      Buffer (Buffer'First .. Buffer'First + 3) :=
        [0, (if Order = Little_Endian then 1 else 0), 0, 0];
   end Put_Header;

   --  One pass: no size pass first. Every byte the write pass stores is
   --  index-checked (ROSIDL.Static.Impl.Wire keeps the checks on), so a buffer
   --  too small stops it with Constraint_Error at its end, never past it;
   --  only then is the size computed, to turn that into Encode_Error (an
   --  error of another origin, the buffer being large enough, propagates).
   procedure Write
     (Msg         : Message;
      With_Header : Boolean;
      Header      : Request_Header;
      Buffer      : out Stream_Element_Array;
      Last        : out Stream_Element_Offset;
      Order       : Byte_Order)
   is
      C : ROSIDL.Static.Impl.Wire.Cursor;
   begin
      Put_Header (Buffer, Order);
      C := (Pos    => Buffer'First + Encapsulation_Size,
            Origin => Buffer'First + Encapsulation_Size,
            Swap   => Order /= Native_Order);
      if With_Header then
         ROSIDL.Static.Impl.Wire.Put_Request_Header (Buffer, C, Header.GUID, Header.Sequence);
      end if;
      Write_Body (Msg, Buffer, C);
      ROSIDL.Static.Impl.Wire.Pad (Buffer, C, 4);
      Last := C.Pos - 1;
   exception
      when Constraint_Error =>
         declare
            Size : constant Stream_Element_Count := Encoded_Size (Msg, With_Header);
         begin
            if Buffer'Length < Size then
               raise Encode_Error with Full_Name & ": buffer of" & Buffer'Length'Image
                 & " bytes, the encoding needs" & Size'Image;
            end if;
         end;
         raise;
   end Write;

   procedure Encode
     (Msg    : Message;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order) is
   begin
      Write (Msg, False, (others => <>), Buffer, Last, Order);
   end Encode;

   procedure Encode
     (Msg    : Message;
      Header : Request_Header;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order := Native_Order) is
   begin
      Write (Msg, True, Header, Buffer, Last, Order);
   end Encode;

   function Encode (Msg : Message; Order : Byte_Order := Native_Order)
      return Stream_Element_Array
   is
      Result : Stream_Element_Array (1 .. Encoded_Size (Msg));
      Last   : Stream_Element_Offset;
   begin
      Encode (Msg, Result, Last, Order);
      return Result;
   end Encode;

   procedure Read
     (Data        : Stream_Element_Array;
      Msg         : in out Message;
      With_Header : Boolean;
      Header      : out Request_Header)
   is
      C : ROSIDL.Static.Impl.Wire.Cursor;
   begin
      Header := (others => <>);
      C := (Pos    => Data'First + Encapsulation_Size,
            Origin => Data'First + Encapsulation_Size,
            Swap   => Byte_Order_Of (Data, Full_Name) /= Native_Order);
      if With_Header then
         Header := ROSIDL.CDR.Request_Header_Of (Data, Full_Name);
         C.Pos := C.Pos + Header_Size;
      end if;
      Read_Body (Data, C, Msg);
   end Read;

   procedure Decode (Data : Stream_Element_Array; Msg : in out Message) is
      Unused : Request_Header;
   begin
      Read (Data, Msg, False, Unused);
   end Decode;

   procedure Decode
     (Data   : Stream_Element_Array;
      Msg    : in out Message;
      Header : out Request_Header) is
   begin
      Read (Data, Msg, True, Header);
   end Decode;

   function Decode (Data : Stream_Element_Array) return Message is
   begin
      return Msg : Message do
         Decode (Data, Msg);
      end return;
   end Decode;

   function Recode (Data : Stream_Element_Array; Order : Byte_Order)
      return Stream_Element_Array is
     (Encode (Decode (Data), Order));

   procedure Recode_Into
     (Data   : Stream_Element_Array;
      Buffer : out Stream_Element_Array;
      Last   : out Stream_Element_Offset;
      Order  : Byte_Order) is
   begin
      Encode (Decode (Data), Buffer, Last, Order);
   end Recode_Into;

   function Round_Trips (Data : Stream_Element_Array) return Boolean is
      X : constant Message := Decode (Data);
   begin
      return Decode (Encode (X, Little_Endian)) = X
        and then Decode (Encode (X, Big_Endian)) = X;
   end Round_Trips;

   function Encode_Default return Stream_Element_Array is
      Default : Message;
      pragma Warnings (Off, Default);
      --  Initialised by the record's component defaults.
   begin
      return Encode (Default, Little_Endian);
   end Encode_Default;

end ROSIDL.Static.Message_Support;
