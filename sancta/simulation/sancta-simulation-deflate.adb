package body Sancta.Simulation.Deflate is

   use Interfaces;

   Max_Bits : constant := 15;

   type Count_Array is array (0 .. Max_Bits) of Natural;
   type Symbol_Array is array (Natural range <>) of Natural;

   type Huffman (Size : Natural) is record
      Count  : Count_Array := [others => 0];
      --  Number of codes of each length.
      Symbol : Symbol_Array (0 .. Size) := [others => 0];
      --  Symbols ordered by code (canonical order).
   end record;

   type Length_Array is array (Natural range <>) of Natural;

   --  Base lengths and extra bits of length symbols 257 .. 285, and of the
   --  distance symbols 0 .. 29 (RFC 1951, 3.2.5).
   Length_Base : constant Length_Array (0 .. 28) :=
     [3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
      35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258];
   Length_Extra : constant Length_Array (0 .. 28) :=
     [0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2,
      3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0];
   Distance_Base : constant Length_Array (0 .. 29) :=
     [1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193,
      257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145,
      8193, 12289, 16385, 24577];
   Distance_Extra : constant Length_Array (0 .. 29) :=
     [0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6,
      7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13];
   Code_Length_Order : constant Length_Array (0 .. 18) :=
     [16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15];

   -------------
   -- Inflate --
   -------------

   procedure Inflate
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer;
      Used   : out Natural)
   is
      Pos      : Natural := Input'First;
      --  Next input byte.
      Bit_Buf  : Unsigned_32 := 0;
      Bit_Cnt  : Natural := 0;
      Out_Pos  : Integer := Output'First;
      --  Next output byte.

      procedure Fail (Reason : String) with No_Return is
      begin
         raise Format_Error with "deflate: byte"
           & Natural'Image (Pos - Input'First) & ": " & Reason;
      end Fail;

      function Bits (N : Natural) return Natural is
         Result : Unsigned_32;
      begin
         while Bit_Cnt < N loop
            if Pos > Input'Last then
               Fail ("truncated stream");
            end if;
            Bit_Buf := Bit_Buf or Shift_Left (Unsigned_32 (Input (Pos)), Bit_Cnt);
            Pos := Pos + 1;
            Bit_Cnt := Bit_Cnt + 8;
         end loop;
         Result := Bit_Buf and (Shift_Left (1, N) - 1);
         Bit_Buf := Shift_Right (Bit_Buf, N);
         Bit_Cnt := Bit_Cnt - N;
         return Natural (Result);
      end Bits;

      procedure Build
        (H : in out Huffman; Lengths : Length_Array; Allow_Incomplete : Boolean)
      is
         Offsets : Count_Array;
         Left    : Integer := 1;
      begin
         H.Count := [others => 0];
         for L of Lengths loop
            H.Count (L) := H.Count (L) + 1;
         end loop;
         if H.Count (0) = Lengths'Length then
            return;  --  No codes: only an error if a symbol is ever decoded.
         end if;
         for Len in 1 .. Max_Bits loop
            Left := Left * 2 - H.Count (Len);
            if Left < 0 then
               Fail ("over-subscribed Huffman code lengths");
            end if;
         end loop;
         if Left > 0 and then not Allow_Incomplete
           and then Lengths'Length - H.Count (0) > 1
         then
            Fail ("incomplete Huffman code lengths");
         end if;
         Offsets (1) := 0;
         for Len in 1 .. Max_Bits - 1 loop
            Offsets (Len + 1) := Offsets (Len) + H.Count (Len);
         end loop;
         for S in Lengths'Range loop
            if Lengths (S) /= 0 then
               H.Symbol (Offsets (Lengths (S))) := S - Lengths'First;
               Offsets (Lengths (S)) := Offsets (Lengths (S)) + 1;
            end if;
         end loop;
      end Build;

      function Decode (H : Huffman) return Natural is
         Code  : Integer := 0;
         First : Integer := 0;
         Index : Integer := 0;
         Count : Integer;
      begin
         for Len in 1 .. Max_Bits loop
            Code := Code + Bits (1);
            Count := H.Count (Len);
            if Code - Count < First then
               return H.Symbol (Index + (Code - First));
            end if;
            Index := Index + Count;
            First := (First + Count) * 2;
            Code := Code * 2;
         end loop;
         Fail ("invalid Huffman code");
      end Decode;

      procedure Put (B : Byte) is
      begin
         if Out_Pos > Output'Last then
            Fail ("output larger than expected");
         end if;
         Output (Out_Pos) := B;
         Out_Pos := Out_Pos + 1;
      end Put;

      procedure Codes (Lit, Dist : Huffman) is
         Symbol : Natural;
         Len    : Natural;
         D      : Natural;
      begin
         loop
            Symbol := Decode (Lit);
            if Symbol < 256 then
               Put (Byte (Symbol));
            elsif Symbol = 256 then
               return;
            elsif Symbol > 285 then
               Fail ("invalid length symbol");
            else
               Len := Length_Base (Symbol - 257) + Bits (Length_Extra (Symbol - 257));
               Symbol := Decode (Dist);
               if Symbol > 29 then
                  Fail ("invalid distance symbol");
               end if;
               D := Distance_Base (Symbol) + Bits (Distance_Extra (Symbol));
               if D > Out_Pos - Output'First then
                  Fail ("distance too far back");
               end if;
               for K in 1 .. Len loop
                  Put (Output (Out_Pos - D));
               end loop;
            end if;
         end loop;
      end Codes;

      procedure Stored is
         Len, NLen : Natural;
      begin
         Bit_Buf := 0;
         Bit_Cnt := 0;
         --  Byte-aligned from here.
         if Pos + 3 > Input'Last then
            Fail ("truncated stored block header");
         end if;
         Len := Natural (Input (Pos)) + 256 * Natural (Input (Pos + 1));
         NLen := Natural (Input (Pos + 2)) + 256 * Natural (Input (Pos + 3));
         if Len /= 65535 - NLen then
            Fail ("stored block length does not match its complement");
         end if;
         Pos := Pos + 4;
         if Len > Input'Last - Pos + 1 then
            Fail ("truncated stored block");
         end if;
         for K in 0 .. Len - 1 loop
            Put (Input (Pos + K));
         end loop;
         Pos := Pos + Len;
      end Stored;

      procedure Fixed is
         Lit  : Huffman (287);
         Dist : Huffman (29);
         Lens : Length_Array (0 .. 287);
      begin
         Lens (0 .. 143) := [others => 8];
         Lens (144 .. 255) := [others => 9];
         Lens (256 .. 279) := [others => 7];
         Lens (280 .. 287) := [others => 8];
         Build (Lit, Lens, True);
         Build (Dist, [0 .. 29 => 5], True);
         Codes (Lit, Dist);
      end Fixed;

      procedure Dynamic is
         HLit  : constant Natural := Bits (5) + 257;
         HDist : constant Natural := Bits (5) + 1;
         HCLen : constant Natural := Bits (4) + 4;
         Lens  : Length_Array (0 .. HLit + HDist - 1) := [others => 0];
         CL    : Length_Array (0 .. 18) := [others => 0];
         CLH   : Huffman (18);
         Index : Natural := 0;
         Sym, Rep, Value : Natural;
      begin
         if HLit > 286 or else HDist > 30 then
            Fail ("too many length or distance codes");
         end if;
         for K in 0 .. HCLen - 1 loop
            CL (Code_Length_Order (K)) := Bits (3);
         end loop;
         Build (CLH, CL, False);
         while Index < Lens'Length loop
            Sym := Decode (CLH);
            if Sym < 16 then
               Lens (Index) := Sym;
               Index := Index + 1;
            else
               if Sym = 16 then
                  if Index = 0 then
                     Fail ("repeat with no previous length");
                  end if;
                  Value := Lens (Index - 1);
                  Rep := 3 + Bits (2);
               elsif Sym = 17 then
                  Value := 0;
                  Rep := 3 + Bits (3);
               else
                  Value := 0;
                  Rep := 11 + Bits (7);
               end if;
               if Index + Rep > Lens'Length then
                  Fail ("too many code lengths");
               end if;
               Lens (Index .. Index + Rep - 1) := [others => Value];
               Index := Index + Rep;
            end if;
         end loop;
         if Lens (256) = 0 then
            Fail ("no end-of-block code");
         end if;
         declare
            Lit  : Huffman (HLit - 1);
            Dist : Huffman (HDist - 1);
         begin
            Build (Lit, Lens (0 .. HLit - 1), False);
            Build (Dist, Lens (HLit .. HLit + HDist - 1), True);
            Codes (Lit, Dist);
         end;
      end Dynamic;

      Final : Boolean := False;
   begin
      while not Final loop
         Final := Bits (1) = 1;
         case Bits (2) is
            when 0 => Stored;
            when 1 => Fixed;
            when 2 => Dynamic;
            when others => Fail ("invalid block type 3");
         end case;
      end loop;
      Last := Out_Pos - 1;
      Used := Pos - Input'First;
   end Inflate;

   ---------------------
   -- Zlib_Decompress --
   ---------------------

   procedure Zlib_Decompress
     (Input  : Byte_Array;
      Output : out Byte_Array;
      Last   : out Integer)
   is
      Used : Natural;
   begin
      if Input'Length < 6 then
         raise Format_Error with "zlib: byte 0: stream too short";
      end if;
      declare
         CMF : constant Byte := Input (Input'First);
         FLG : constant Byte := Input (Input'First + 1);
      begin
         if (CMF and 16#0F#) /= 8 or else Shift_Right (CMF, 4) > 7 then
            raise Format_Error with "zlib: byte 0: compression method is not deflate";
         end if;
         if (Natural (CMF) * 256 + Natural (FLG)) mod 31 /= 0 then
            raise Format_Error with "zlib: byte 1: header check failed";
         end if;
         if (FLG and 16#20#) /= 0 then
            raise Format_Error with "zlib: byte 1: preset dictionary not supported";
         end if;
      end;
      Inflate (Input (Input'First + 2 .. Input'Last), Output, Last, Used);
      declare
         P : constant Natural := Input'First + 2 + Used;
         Expected : Unsigned_32 := 0;
      begin
         if P + 3 > Input'Last then
            raise Format_Error with "zlib: byte" & Natural'Image (P - Input'First)
              & ": missing Adler-32 checksum";
         end if;
         for K in 0 .. 3 loop
            Expected := Shift_Left (Expected, 8) or Unsigned_32 (Input (P + K));
         end loop;
         if Adler_32 (Output (Output'First .. Last)) /= Expected then
            raise Format_Error with "zlib: byte" & Natural'Image (P - Input'First)
              & ": Adler-32 checksum mismatch";
         end if;
      end;
   end Zlib_Decompress;

   ----------------
   -- Zlib_Store --
   ----------------

   function Zlib_Store (Data : Byte_Array) return Byte_Array is
      Block   : constant := 65_535;
      Blocks  : constant Natural := Natural'Max (1, (Data'Length + Block - 1) / Block);
      Result  : Byte_Array (0 .. 2 + Blocks * 5 + Data'Length + 4 - 1);
      P       : Natural := 2;
      Start   : Natural := Data'First;
      A       : constant Unsigned_32 := Adler_32 (Data);
   begin
      Result (0) := 16#78#;
      Result (1) := 16#01#;
      for B in 1 .. Blocks loop
         declare
            Len : constant Natural := Natural'Min (Block, Data'Last - Start + 1);
         begin
            Result (P) := (if B = Blocks then 1 else 0);
            Result (P + 1) := Byte (Len mod 256);
            Result (P + 2) := Byte (Len / 256);
            Result (P + 3) := Byte ((65_535 - Len) mod 256);
            Result (P + 4) := Byte ((65_535 - Len) / 256);
            P := P + 5;
            Result (P .. P + Len - 1) := Data (Start .. Start + Len - 1);
            P := P + Len;
            Start := Start + Len;
         end;
      end loop;
      for K in 0 .. 3 loop
         Result (P + K) := Byte (Shift_Right (A, 8 * (3 - K)) and 16#FF#);
      end loop;
      return Result;
   end Zlib_Store;

   function Adler_32 (Data : Byte_Array) return Unsigned_32 is
      A : Unsigned_32 := 1;
      B : Unsigned_32 := 0;
   begin
      for D of Data loop
         A := (A + Unsigned_32 (D)) mod 65_521;
         B := (B + A) mod 65_521;
      end loop;
      return Shift_Left (B, 16) or A;
   end Adler_32;

   type CRC_Table is array (Byte) of Unsigned_32;

   function Make_Table return CRC_Table is
      T : CRC_Table;
      C : Unsigned_32;
   begin
      for N in Byte loop
         C := Unsigned_32 (N);
         for K in 1 .. 8 loop
            C := (if (C and 1) /= 0 then 16#EDB8_8320# xor Shift_Right (C, 1)
                  else Shift_Right (C, 1));
         end loop;
         T (N) := C;
      end loop;
      return T;
   end Make_Table;

   Table : constant CRC_Table := Make_Table;

   function CRC_32
     (Data    : Byte_Array;
      Initial : Unsigned_32 := 0) return Unsigned_32
   is
      C : Unsigned_32 := Initial xor 16#FFFF_FFFF#;
   begin
      for D of Data loop
         C := Table (Byte (C and 16#FF#) xor D) xor Shift_Right (C, 8);
      end loop;
      return C xor 16#FFFF_FFFF#;
   end CRC_32;

end Sancta.Simulation.Deflate;
