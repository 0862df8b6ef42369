with Ada.Unchecked_Deallocation;

package body RCL.MCAP.Buffers is

   use Interfaces;

   procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Byte_Array_Access);

   procedure Reserve (This : in out Buffer; Extra : Stream_Element_Offset) is
      Needed : constant Stream_Element_Offset := This.Length + Extra;
   begin
      if This.Data = null or else This.Data'Last < Needed then
         declare
            Capacity : Stream_Element_Offset :=
              (if This.Data = null then 4096 else This.Data'Length);
            Bigger   : Byte_Array_Access;
         begin
            while Capacity < Needed loop
               Capacity := Capacity * 2;
            end loop;
            Bigger := new Byte_Array (1 .. Capacity);
            if This.Data /= null then
               Bigger (1 .. This.Length) := This.Data (1 .. This.Length);
               Free (This.Data);
            end if;
            This.Data := Bigger;
         end;
      end if;
   end Reserve;

   procedure Swap (Left, Right : in out Buffer) is
      Data   : constant Byte_Array_Access := Left.Data;
      Length : constant Stream_Element_Offset := Left.Length;
   begin
      Left.Data := Right.Data;
      Left.Length := Right.Length;
      Right.Data := Data;
      Right.Length := Length;
   end Swap;

   procedure Clear (This : in out Buffer) is
   begin
      This.Length := 0;
   end Clear;

   procedure Put_U8 (This : in out Buffer; Value : Unsigned_8) is
   begin
      Reserve (This, 1);
      This.Length := This.Length + 1;
      This.Data (This.Length) := Stream_Element (Value);
   end Put_U8;

   procedure Put_U16 (This : in out Buffer; Value : Unsigned_16) is
   begin
      Reserve (This, 2);
      This.Data (This.Length + 1) := Stream_Element (Value and 16#FF#);
      This.Data (This.Length + 2) := Stream_Element (Shift_Right (Value, 8));
      This.Length := This.Length + 2;
   end Put_U16;

   procedure Put_U32 (This : in out Buffer; Value : Unsigned_32) is
   begin
      Reserve (This, 4);
      for I in 0 .. 3 loop
         This.Data (This.Length + 1 + Stream_Element_Offset (I)) :=
           Stream_Element (Shift_Right (Value, 8 * I) and 16#FF#);
      end loop;
      This.Length := This.Length + 4;
   end Put_U32;

   procedure Encode_U64 (Into : in out Byte_Array; At_Index : Stream_Element_Offset;
                         Value : Unsigned_64) is
   begin
      for I in 0 .. 7 loop
         Into (At_Index + Stream_Element_Offset (I)) :=
           Stream_Element (Shift_Right (Value, 8 * I) and 16#FF#);
      end loop;
   end Encode_U64;

   procedure Put_U64 (This : in out Buffer; Value : Unsigned_64) is
   begin
      Reserve (This, 8);
      Encode_U64 (This.Data.all, This.Length + 1, Value);
      This.Length := This.Length + 8;
   end Put_U64;

   procedure Put_Bytes (This : in out Buffer; Data : Byte_Array) is
   begin
      Reserve (This, Data'Length);
      This.Data (This.Length + 1 .. This.Length + Data'Length) := Data;
      This.Length := This.Length + Data'Length;
   end Put_Bytes;

   procedure Put_String (This : in out Buffer; Text : String) is
   begin
      Put_U32 (This, Unsigned_32 (Text'Length));
      Reserve (This, Text'Length);
      for C of Text loop
         This.Length := This.Length + 1;
         This.Data (This.Length) := Character'Pos (C);
      end loop;
   end Put_String;

   procedure Put_Map (This : in out Buffer; Map : String_Maps.Map) is
      Size : Unsigned_32 := 0;
   begin
      for C in Map.Iterate loop
         Size := Size + 8 + Unsigned_32 (String_Maps.Key (C)'Length)
           + Unsigned_32 (String_Maps.Element (C)'Length);
      end loop;
      Put_U32 (This, Size);
      for C in Map.Iterate loop
         Put_String (This, String_Maps.Key (C));
         Put_String (This, String_Maps.Element (C));
      end loop;
   end Put_Map;

   procedure Patch_U64 (This : in out Buffer; At_Index : Stream_Element_Offset;
                        Value : Unsigned_64) is
   begin
      Encode_U64 (This.Data.all, At_Index, Value);
   end Patch_U64;

   overriding procedure Finalize (This : in out Buffer) is
   begin
      Free (This.Data);
      This.Length := 0;
   end Finalize;

end RCL.MCAP.Buffers;
