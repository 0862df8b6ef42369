--  Growable byte buffers with MCAP's little-endian encoding
--  of integers, strings (uint32 length, then the bytes) and byte fields.
--  Example:
--     B.Put_U8 (16#05#);  B.Put_U64 (Length);  B.Put_String ("/chatter");
with Ada.Finalization;

private package RCL.MCAP.Buffers is

   use Ada.Streams;

   type Byte_Array_Access is access Byte_Array;

   type Buffer is new Ada.Finalization.Limited_Controlled with record
      Data   : Byte_Array_Access;
      Length : Stream_Element_Offset := 0;
      --  The bytes held are Data (1 .. Length).
   end record;

   procedure Reserve (This : in out Buffer; Extra : Stream_Element_Offset);
   --  Room for Extra more bytes (the capacity at least doubles).

   procedure Swap (Left, Right : in out Buffer);
   --  Exchanges the bytes (and the memory) of Left and Right, no copy.

   procedure Clear (This : in out Buffer);
   --  Length := 0, keeping the memory.

   procedure Put_U8 (This : in out Buffer; Value : Interfaces.Unsigned_8);
   procedure Put_U16 (This : in out Buffer; Value : Interfaces.Unsigned_16);
   procedure Put_U32 (This : in out Buffer; Value : Interfaces.Unsigned_32);
   procedure Put_U64 (This : in out Buffer; Value : Interfaces.Unsigned_64);
   procedure Put_Bytes (This : in out Buffer; Data : Byte_Array);
   procedure Put_String (This : in out Buffer; Text : String);
   --  uint32 length, then the characters.
   procedure Put_Map (This : in out Buffer; Map : String_Maps.Map);
   --  uint32 byte length, then key and value strings.

   procedure Patch_U64 (This : in out Buffer; At_Index : Stream_Element_Offset;
                        Value : Interfaces.Unsigned_64)
     with Pre => At_Index + 7 <= This.Length;
   --  Overwrites 8 bytes from At_Index (a length known only afterwards).

   overriding procedure Finalize (This : in out Buffer);

   procedure Encode_U64 (Into : in out Byte_Array; At_Index : Stream_Element_Offset;
                         Value : Interfaces.Unsigned_64);

end RCL.MCAP.Buffers;
