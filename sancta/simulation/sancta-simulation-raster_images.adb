with Ada.Directories;
with Ada.Exceptions;
with Ada.Streams.Stream_IO;
with Ada.Unchecked_Deallocation;
with Interfaces;

package body Sancta.Simulation.Raster_Images is

   use Deflate;
   use type Ada.Directories.File_Kind;
   use Interfaces;

   procedure Free is new Ada.Unchecked_Deallocation (Pixel_Matrix, Pixel_Access);
   procedure Free is new Ada.Unchecked_Deallocation (Byte_Array, Byte_Array_Access);

   function Create (Width, Height : Natural; Fill : Color := White) return Image is
   begin
      return Result : Image do
         Result.Pixels := new Pixel_Matrix'(1 .. Height => [1 .. Width => Fill]);
      end return;
   end Create;

   function Width (This : Image) return Natural is
     (if This.Pixels = null then 0 else This.Pixels'Length (2));

   function Height (This : Image) return Natural is
     (if This.Pixels = null then 0 else This.Pixels'Length (1));

   function Get (This : Image; X, Y : Positive) return Color is
     (This.Pixels (Y, X));

   procedure Set (This : in out Image; X, Y : Integer; C : Color) is
   begin
      if X in 1 .. Width (This) and then Y in 1 .. Height (This) then
         This.Pixels (Y, X) := C;
      end if;
   end Set;

   ---------------
   -- Read_File --
   ---------------

   function Read_File (File_Name : String) return Byte_Array is
      use Ada.Streams.Stream_IO;
      F : File_Type;
   begin
      if not Ada.Directories.Exists (File_Name) then
         raise Format_Error with File_Name & ": no such file";
      elsif Ada.Directories.Kind (File_Name) /= Ada.Directories.Ordinary_File then
         raise Format_Error with File_Name & ": not a regular file";
      end if;
      declare
         Size : constant Natural := Natural (Ada.Directories.Size (File_Name));
         Data : Byte_Array_Access := new Byte_Array (0 .. Size - 1);
      begin
         Open (F, In_File, File_Name);
         Byte_Array'Read (Stream (F), Data.all);
         Close (F);
         return Result : constant Byte_Array := Data.all do
            Free (Data);
         end return;
      end;
   exception
      when Format_Error =>
         raise;
      when others =>
         raise Format_Error with File_Name & ": cannot be read";
   end Read_File;

   procedure Fail_At (Name : String; Offset : Natural; Reason : String) with No_Return;
   --  Format_Error "NAME: byte OFFSET: REASON".

   procedure Fail_At (Name : String; Offset : Natural; Reason : String) is
   begin
      raise Format_Error with Name & ": byte" & Natural'Image (Offset) & ": " & Reason;
   end Fail_At;

   ----------------
   -- Decode_PGM --
   ----------------

   function Decode_PGM (Data : Byte_Array; Name : String) return Image is
      Pos : Natural := Data'First;

      procedure Fail (Reason : String) with No_Return is
      begin
         Fail_At (Name, Pos - Data'First, Reason);
      end Fail;

      function Is_Space (B : Byte) return Boolean is
        (B in 9 .. 13 or else B = 32);

      procedure Skip_Blanks is
      begin
         while Pos <= Data'Last loop
            if Data (Pos) = Character'Pos ('#') then
               while Pos <= Data'Last and then Data (Pos) /= 10 loop
                  Pos := Pos + 1;
               end loop;
            elsif Is_Space (Data (Pos)) then
               Pos := Pos + 1;
            else
               exit;
            end if;
         end loop;
      end Skip_Blanks;

      function Number (What : String; Limit : Natural) return Natural is
         Value : Natural := 0;
         Start : Natural;
      begin
         Skip_Blanks;
         Start := Pos;
         while Pos <= Data'Last and then Data (Pos) in 48 .. 57 loop
            if Value > Limit / 10 then
               Fail (What & " too large (at most" & Limit'Image & ")");
            end if;
            Value := Value * 10 + Natural (Data (Pos)) - 48;
            Pos := Pos + 1;
         end loop;
         if Pos = Start then
            Fail ("expected " & What & " (a decimal number)");
         end if;
         if Value > Limit then
            Fail (What & " too large (at most" & Limit'Image & ")");
         end if;
         return Value;
      end Number;

      Binary : Boolean;
   begin
      if Data'Length < 2 or else Data (Data'First) /= Character'Pos ('P')
        or else Data (Data'First + 1) not in Character'Pos ('2') | Character'Pos ('5')
      then
         Fail ("not a PGM file (expected ""P5"" or ""P2"")");
      end if;
      Binary := Data (Data'First + 1) = Character'Pos ('5');
      Pos := Data'First + 2;
      declare
         W      : constant Natural := Number ("width", Max_Side);
         H      : constant Natural := Number ("height", Max_Side);
         Max    : constant Natural := Number ("maximum gray value", 65_535);
         Result : Image;
         V      : Natural;
      begin
         if W = 0 or else H = 0 then
            Fail ("empty image");
         end if;
         if W * H > Max_Pixels then
            Fail ("image too large (over" & Max_Pixels'Image & " pixels)");
         end if;
         if Max = 0 then
            Fail ("maximum gray value must be positive");
         end if;
         if Binary then
            if Pos > Data'Last or else not Is_Space (Data (Pos)) then
               Fail ("expected one blank after the maximum gray value");
            end if;
            Pos := Pos + 1;
            declare
               Sample : constant Natural := (if Max < 256 then 1 else 2);
               Needed : constant Natural := W * H * Sample;
            begin
               if Data'Last - Pos + 1 < Needed then
                  Fail ("truncated pixel data: expected" & Needed'Image
                        & " bytes, found" & Natural'Image (Data'Last - Pos + 1));
               end if;
               Result := Create (W, H);
               for Y in 1 .. H loop
                  for X in 1 .. W loop
                     V := (if Sample = 1 then Natural (Data (Pos))
                           else Natural (Data (Pos)) * 256 + Natural (Data (Pos + 1)));
                     if V > Max then
                        Fail ("sample above the maximum gray value");
                     end if;
                     V := V * 255 / Max;
                     Result.Pixels (Y, X) := (Byte (V), Byte (V), Byte (V));
                     Pos := Pos + Sample;
                  end loop;
               end loop;
            end;
         else
            Result := Create (W, H);
            for Y in 1 .. H loop
               for X in 1 .. W loop
                  V := Number ("a gray value", Max);
                  V := V * 255 / Max;
                  Result.Pixels (Y, X) := (Byte (V), Byte (V), Byte (V));
               end loop;
            end loop;
         end if;
         return Result;
      end;
   end Decode_PGM;

   ----------------
   -- Decode_PNG --
   ----------------

   Signature : constant Byte_Array (0 .. 7) := [137, 80, 78, 71, 13, 10, 26, 10];

   function Decode_PNG (Data : Byte_Array; Name : String) return Image is
      Pos : Natural := Data'First;

      procedure Fail (Reason : String) with No_Return is
      begin
         Fail_At (Name, Pos - Data'First, Reason);
      end Fail;

      function U32 (P : Natural) return Unsigned_32 is
        (Shift_Left (Unsigned_32 (Data (P)), 24) or Shift_Left (Unsigned_32 (Data (P + 1)), 16)
         or Shift_Left (Unsigned_32 (Data (P + 2)), 8) or Unsigned_32 (Data (P + 3)));

      function Kind (P : Natural) return String is
        ([for K in 1 .. 4 => Character'Val (Data (P + K - 1))]);

      function Hex (P : Natural) return String is
         --  The 4 bytes at P in hex ("00 01 41 ff"), for a chunk type that
         --  is not letters.
         Hex_Digits : constant String := "0123456789abcdef";
      begin
         return [for K in 1 .. 11 =>
                   (if K mod 3 = 0 then ' '
                    elsif K mod 3 = 1 then Hex_Digits (Natural (Data (P + K / 3)) / 16 + 1)
                    else Hex_Digits (Natural (Data (P + K / 3)) mod 16 + 1))];
      end Hex;

      W, H          : Natural := 0;
      Depth, CType  : Natural := 0;
      Seen_Header   : Boolean := False;
      Seen_End      : Boolean := False;
      Palette       : array (0 .. 255) of Color := [others => Black];
      Palette_Size  : Natural := 0;
      Seen_Palette  : Boolean := False;
      IDAT          : Byte_Array_Access := new Byte_Array (0 .. Data'Length);
      IDAT_Length   : Natural := 0;
      Seen_IDAT     : Boolean := False;
      IDAT_Ended    : Boolean := False;
      --  A chunk other than IDAT came after the first IDAT.
   begin
      if Data'Length < 8 or else Data (Data'First .. Data'First + 7) /= Signature then
         Free (IDAT);
         Fail ("not a PNG file (bad signature)");
      end if;
      Pos := Data'First + 8;
      while not Seen_End loop
         if Data'Last - Pos + 1 < 12 then
            Fail ("truncated chunk (no IEND)");
         end if;
         declare
            Length : constant Unsigned_32 := U32 (Pos);
            T      : constant String := Kind (Pos + 4);
            First  : constant Natural := Pos + 8;
            Valid  : constant Boolean := (for all Letter of T => Letter in 'A' .. 'Z' | 'a' .. 'z');
            Named  : constant String := (if Valid then T else Hex (Pos + 4));
            --  The chunk type for messages.
         begin
            if Length > Unsigned_32 (Data'Last - Pos + 1 - 12) then
               Fail ("chunk " & Named & " longer than the file");
            end if;
            declare
               Last : constant Integer := First + Integer (Length) - 1;
               C    : constant Byte_Array := Data (First .. Last);
            begin
               if CRC_32 (Data (Pos + 4 .. Last)) /= U32 (Last + 1) then
                  Fail ("CRC mismatch in chunk " & Named);
               elsif not Valid then
                  Fail ("chunk type " & Named & " is not four ASCII letters");
               end if;
               if not Seen_Header and then T /= "IHDR" then
                  Fail ("first chunk is " & T & ", not IHDR");
               elsif T (1) in 'A' .. 'Z' and then T not in "IHDR" | "PLTE" | "IDAT" | "IEND" then
                  Fail ("unknown critical chunk " & T & " (the image cannot be read without it)");
               elsif T = "IDAT" and then IDAT_Ended then
                  Fail ("IDAT chunks are not consecutive");
               end if;
               IDAT_Ended := Seen_IDAT and then T /= "IDAT";
               if T = "IHDR" and then Seen_Header then
                  Fail ("second IHDR chunk");
               elsif T = "IHDR" then
                  if Length /= 13 then
                     Fail ("IHDR length is not 13");
                  end if;
                  if U32 (First) > Max_Side or else U32 (First + 4) > Max_Side
                    or else U32 (First) = 0 or else U32 (First + 4) = 0
                  then
                     Fail ("image size out of range 1 .." & Max_Side'Image);
                  end if;
                  W := Natural (U32 (First));
                  H := Natural (U32 (First + 4));
                  if W * H > Max_Pixels then
                     Fail ("image too large (over" & Max_Pixels'Image & " pixels)");
                  end if;
                  Depth := Natural (C (C'First + 8));
                  CType := Natural (C (C'First + 9));
                  if not (case CType is
                            when 0 => Depth in 1 | 2 | 4 | 8 | 16,
                            when 3 => Depth in 1 | 2 | 4 | 8,
                            when 2 | 4 | 6 => Depth in 8 | 16,
                            when others => False)
                  then
                     Fail ("invalid colour type" & CType'Image & " with bit depth"
                           & Depth'Image);
                  end if;
                  if C (C'First + 10) /= 0 or else C (C'First + 11) /= 0 then
                     Fail ("unknown compression or filter method");
                  end if;
                  if C (C'First + 12) /= 0 then
                     Fail ("interlaced PNG images are not supported");
                  end if;
                  Seen_Header := True;
               elsif T = "PLTE" then
                  if Seen_Palette then
                     Fail ("second PLTE chunk");
                  elsif Seen_IDAT then
                     Fail ("PLTE chunk after the image data");
                  elsif CType in 0 | 4 then
                     Fail ("PLTE chunk in a grey image (colour type" & CType'Image & ")");
                  elsif Length = 0 or else Length mod 3 /= 0 or else Length > 768 then
                     Fail ("bad palette length" & Length'Image);
                  end if;
                  Seen_Palette := True;
                  Palette_Size := Natural (Length) / 3;
                  for K in 0 .. Palette_Size - 1 loop
                     Palette (K) := (C (C'First + 3 * K), C (C'First + 3 * K + 1),
                                     C (C'First + 3 * K + 2));
                  end loop;
               elsif T = "IDAT" then
                  Seen_IDAT := True;
                  IDAT (IDAT_Length .. IDAT_Length + C'Length - 1) := C;
                  IDAT_Length := IDAT_Length + C'Length;
               elsif T = "IEND" then
                  Seen_End := True;
               end if;
               Pos := Last + 5;
            end;
         end;
      end loop;
      if CType = 3 and then Palette_Size = 0 then
         Fail ("palette image without PLTE");
      end if;
      declare
         Channels : constant Natural :=
           (case CType is when 0 | 3 => 1, when 4 => 2, when 2 => 3, when others => 4);
         Bits     : constant Natural := Channels * Depth;
         Bpp      : constant Natural := Natural'Max (1, Bits / 8);
         Stride   : constant Natural := (W * Bits + 7) / 8;
         Raw      : Byte_Array_Access := new Byte_Array (0 .. H * (Stride + 1) - 1);
         Last     : Integer;
         Result   : constant Image := Create (W, H);

         function Sample (Row, Index : Natural) return Natural is
            --  Sample Index (from 0) of the unfiltered row, scaled to 0 .. 255.
            Base : constant Natural := Row * (Stride + 1) + 1;
         begin
            case Depth is
               when 8 => return Natural (Raw (Base + Index));
               when 16 => return Natural (Raw (Base + 2 * Index));
               when others =>
                  declare
                     Bit   : constant Natural := Index * Depth;
                     B     : constant Unsigned_8 := Raw (Base + Bit / 8);
                     Shift : constant Natural := 8 - Depth - Bit mod 8;
                     V     : constant Natural := Natural
                       (Shift_Right (B, Shift) and (Shift_Left (1, Depth) - 1));
                  begin
                     return (if CType = 3 then V else V * 255 / (2 ** Depth - 1));
                  end;
            end case;
         end Sample;
      begin
         begin
            Zlib_Decompress (IDAT (0 .. IDAT_Length - 1), Raw.all, Last);
         exception
            when E : Format_Error =>
               Free (IDAT);
               Free (Raw);
               raise Format_Error with Name & ": image data: "
                 & Ada.Exceptions.Exception_Message (E);
         end;
         Free (IDAT);
         if Last /= Raw'Last then
            Free (Raw);
            Fail ("image data too short");
         end if;
         --  Undo the filters, row by row.
         for Row in 0 .. H - 1 loop
            declare
               Base : constant Natural := Row * (Stride + 1);
               F    : constant Byte := Raw (Base);

               function Up (K : Natural) return Natural is
                 (if Row = 0 then 0 else Natural (Raw (Base - (Stride + 1) + 1 + K)));
               function Left (K : Natural) return Natural is
                 (if K < Bpp then 0 else Natural (Raw (Base + 1 + K - Bpp)));
               function Up_Left (K : Natural) return Natural is
                 (if Row = 0 or else K < Bpp then 0
                  else Natural (Raw (Base - (Stride + 1) + 1 + K - Bpp)));
               function Paeth (A, B, C : Natural) return Natural is
                  P  : constant Integer := A + B - C;
                  PA : constant Natural := abs (P - A);
                  PB : constant Natural := abs (P - B);
                  PC : constant Natural := abs (P - C);
               begin
                  return (if PA <= PB and then PA <= PC then A elsif PB <= PC then B else C);
               end Paeth;
               Add : Natural;
            begin
               if F > 4 then
                  Free (Raw);
                  Fail ("image row" & Row'Image & ": invalid filter type" & F'Image);
               end if;
               for K in 0 .. Stride - 1 loop
                  Add := (case F is
                            when 0 => 0,
                            when 1 => Left (K),
                            when 2 => Up (K),
                            when 3 => (Left (K) + Up (K)) / 2,
                            when others => Paeth (Left (K), Up (K), Up_Left (K)));
                  Raw (Base + 1 + K) := Byte ((Natural (Raw (Base + 1 + K)) + Add) mod 256);
               end loop;
            end;
         end loop;
         for Y in 1 .. H loop
            for X in 1 .. W loop
               declare
                  Row : constant Natural := Y - 1;
                  I   : constant Natural := (X - 1) * Channels;
               begin
                  case CType is
                     when 0 | 4 =>
                        Result.Pixels (Y, X) :=
                          (others => Byte (Sample (Row, I)));
                     when 3 =>
                        if Sample (Row, I) >= Palette_Size then
                           Free (Raw);
                           Fail ("palette index out of range in row" & Row'Image);
                        end if;
                        Result.Pixels (Y, X) := Palette (Sample (Row, I));
                     when others =>
                        Result.Pixels (Y, X) :=
                          (Byte (Sample (Row, I)), Byte (Sample (Row, I + 1)),
                           Byte (Sample (Row, I + 2)));
                  end case;
               end;
            end loop;
         end loop;
         Free (Raw);
         return Result;
      end;
   end Decode_PNG;

   ----------
   -- Load --
   ----------

   function Load (File_Name : String) return Image is
      Data : constant Byte_Array := Read_File (File_Name);
   begin
      if Data'Length >= 8 and then Data (0 .. 7) = Signature then
         return Decode_PNG (Data, File_Name);
      else
         return Decode_PGM (Data, File_Name);
      end if;
   end Load;

   ----------------
   -- Encode_PNG --
   ----------------

   function Encode_PNG (This : Image) return Byte_Array is
      W   : constant Natural := Width (This);
      H   : constant Natural := Height (This);
      Raw : Byte_Array_Access := new Byte_Array (0 .. H * (3 * W + 1) - 1);

      function Be (V : Unsigned_32) return Byte_Array is
        [Byte (Shift_Right (V, 24)), Byte (Shift_Right (V, 16) and 255),
         Byte (Shift_Right (V, 8) and 255), Byte (V and 255)];

      function Chunk (T : String; Body_Data : Byte_Array) return Byte_Array is
         Tag : constant Byte_Array := [for C of T => Byte (Character'Pos (C))];
      begin
         return Be (Body_Data'Length) & Tag & Body_Data
           & Be (CRC_32 (Tag & Body_Data));
      end Chunk;
   begin
      for Y in 1 .. H loop
         declare
            Base : constant Natural := (Y - 1) * (3 * W + 1);
         begin
            Raw (Base) := 0;
            for X in 1 .. W loop
               Raw (Base + 3 * X - 2) := This.Pixels (Y, X).R;
               Raw (Base + 3 * X - 1) := This.Pixels (Y, X).G;
               Raw (Base + 3 * X) := This.Pixels (Y, X).B;
            end loop;
         end;
      end loop;
      declare
         Z : constant Byte_Array := Zlib_Store (Raw.all);
      begin
         Free (Raw);
         return Signature
           & Chunk ("IHDR", Be (Unsigned_32 (W)) & Be (Unsigned_32 (H)) & [8, 2, 0, 0, 0])
           & Chunk ("IDAT", Z)
           & Chunk ("IEND", [1 .. 0 => 0]);
      end;
   end Encode_PNG;

   procedure Write_File (File_Name : String; Data : Byte_Array) is
      use Ada.Streams.Stream_IO;
      F : File_Type;
   begin
      Create (F, Out_File, File_Name);
      Byte_Array'Write (Stream (F), Data);
      Close (F);
   end Write_File;

   procedure Save_PNG (This : Image; File_Name : String) is
   begin
      Write_File (File_Name, Encode_PNG (This));
   end Save_PNG;

   procedure Save_PGM (This : Image; File_Name : String) is
      Header : constant String := "P5" & ASCII.LF & "# SANCTA map" & ASCII.LF
        & Natural'Image (Width (This)) & Natural'Image (Height (This)) & ASCII.LF
        & "255" & ASCII.LF;
      Data   : Byte_Array_Access :=
        new Byte_Array (0 .. Header'Length + Width (This) * Height (This) - 1);
      P      : Natural := Header'Length;
   begin
      for K in Header'Range loop
         Data (K - Header'First) := Character'Pos (Header (K));
      end loop;
      for Y in 1 .. Height (This) loop
         for X in 1 .. Width (This) loop
            Data (P) := Gray (This.Pixels (Y, X));
            P := P + 1;
         end loop;
      end loop;
      Write_File (File_Name, Data.all);
      Free (Data);
   end Save_PGM;

   overriding procedure Adjust (This : in out Image) is
   begin
      if This.Pixels /= null then
         This.Pixels := new Pixel_Matrix'(This.Pixels.all);
      end if;
   end Adjust;

   overriding procedure Finalize (This : in out Image) is
   begin
      Free (This.Pixels);
   end Finalize;

end Sancta.Simulation.Raster_Images;
