with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;  use Ada.Strings.Unbounded;
with AUnit.Assertions;   use AUnit.Assertions;
with Interfaces;
with Sancta.Simulation.Zlib;  use Sancta.Simulation.Zlib;
with Suite_Support; use Suite_Support;

package body Sancta.Simulation.Map_Files.Tests is

   use Raster_Images;
   use type Interfaces.Unsigned_32;
   use type Interfaces.Unsigned_8;

   subtype Byte is Zlib.Byte;

   Dir : constant String := "tests/data/simulation/";

   function Bytes (S : String) return Byte_Array is
     [for K in S'Range => Byte (Character'Pos (S (K)))];

   --------------------------------------------------------------------

   procedure Checksums (Unused : in out Fixture) is
   begin
      Assert (CRC_32 (Bytes ("123456789")) = 16#CBF4_3926#, "CRC-32 check value");
      Assert (CRC_32 (Bytes ("6789"), CRC_32 (Bytes ("12345"))) = 16#CBF4_3926#,
              "CRC-32 continued");
   end Checksums;

   procedure Zlib_Known_Streams (Unused : in out Fixture) is
      Fixed_Stream : constant Byte_Array :=
        [120, 218, 203, 72, 205, 201, 201, 87, 200, 64, 39, 1, 104, 3, 8, 177];
      Stored_Stream : constant Byte_Array :=
        [120, 1, 1, 3, 0, 252, 255, 97, 98, 99, 2, 77, 1, 39];
      Output : Byte_Array (0 .. 9_999);
      Last   : Integer;
   begin
      Decompress (Fixed_Stream, Output, Last);
      Assert (Output (0 .. Last) = Bytes ("hello hello hello hello"), "fixed Huffman block");
      Decompress (Stored_Stream, Output, Last);
      Assert (Output (0 .. Last) = Bytes ("abc"), "stored block");
      declare
         Packed : constant Byte_Array := Raster_Images.Read_File (Dir & "dynamic.zz");
         Plain  : constant Byte_Array := Raster_Images.Read_File (Dir & "dynamic.txt");
         Bad    : Byte_Array := Packed;
         Raised : Boolean := False;
      begin
         Assert ((Packed (2) / 2) mod 4 = 2, "fixture is a dynamic Huffman block");
         Decompress (Packed, Output, Last);
         Assert (Output (0 .. Last) = Plain, "dynamic Huffman block");
         Assert (Compress (Plain)'Length < Plain'Length, "text is compressed");
         Decompress (Compress (Plain), Output, Last);
         Assert (Output (0 .. Last) = Plain, "round trip");
         Decompress (Compress ([1 .. 0 => 0]), Output, Last);
         Assert (Last = Output'First - 1, "round trip of nothing");
         Bad (Bad'Last - 8) := Bad (Bad'Last - 8) xor 16#55#;
         begin
            Decompress (Bad, Output, Last);
         exception
            when Format_Error => Raised := True;
         end;
         Assert (Raised, "a corrupted stream is refused");
         Raised := False;
         begin
            Decompress (Packed (0 .. 15), Output, Last);
         exception
            when E : Format_Error =>
               Raised := Contains (Ada.Exceptions.Exception_Message (E), "byte");
         end;
         Assert (Raised, "a truncated stream is refused with a byte offset");
         Raised := False;
         declare
            Small : Byte_Array (0 .. 99);
         begin
            Decompress (Packed, Small, Last);
         exception
            when Format_Error => Raised := True;
         end;
         Assert (Raised, "no over-run of a too small output");
         declare
            Message : Unbounded_String := To_Unbounded_String ("no error");
         begin
            begin
               --  FDICT set (0x78BB is a multiple of 31), dictionary id 1.
               Decompress ([16#78#, 16#BB#, 0, 0, 0, 1, 3, 0, 0, 0, 0, 1], Output, Last);
            exception
               when E : Format_Error =>
                  Message := To_Unbounded_String (Ada.Exceptions.Exception_Message (E));
            end;
            Assert (Message = "zlib: byte 6: preset dictionary not supported",
                    "a preset dictionary is refused after its 6 header bytes: "
                    & To_String (Message));
         end;
         --  Every byte flipped, with three patterns: Format_Error or a
         --  result, never another exception.
         for K in Packed'Range loop
            for Pattern of Byte_Array'[16#01#, 16#5A#, 16#FF#] loop
               declare
                  Fuzzed : Byte_Array := Packed;
               begin
                  Fuzzed (K) := Fuzzed (K) xor Pattern;
                  Decompress (Fuzzed, Output, Last);
               exception
                  when Format_Error => null;
               end;
            end loop;
         end loop;
      end;
   end Zlib_Known_Streams;

   procedure PNG_Round_Trip (Unused : in out Fixture) is
      A : Image := Create (37, 11, White);
   begin
      for X in 1 .. 37 loop
         Set (A, X, 1 + X mod 11, (Byte (X * 5), Byte (255 - X), 7));
      end loop;
      declare
         B : constant Image := Decode_PNG (Encode_PNG (A), "memory");
      begin
         Assert (Width (B) = 37 and then Height (B) = 11, "size");
         for Y in 1 .. 11 loop
            for X in 1 .. 37 loop
               Assert (Get (A, X, Y) = Get (B, X, Y), "pixel" & X'Image & Y'Image);
            end loop;
         end loop;
      end;
   end PNG_Round_Trip;

   function Expected_Gray (X, Y : Natural) return Byte is
     --  The pattern of make_fixtures.py (0-based X, Y from the top).
     (if X in 0 | 19 or else Y in 0 | 9 then 0
      elsif X = 5 and then Y = 2 then 205
      elsif X in 12 .. 13 and then Y in 4 .. 5 then 0
      else 254);

   procedure Image_Formats (Unused : in out Fixture) is
      type Name_List is array (1 .. 4) of String (1 .. 12);
      Names : constant Name_List :=
        ["room.pgm    ", "room_p2.pgm ", "room.png    ", "room_rgb.png"];
   begin
      for Name of Names loop
         declare
            File : constant String := Dir & Ada.Strings.Fixed.Trim (Name, Ada.Strings.Right);
            I    : constant Image := Load (File);
         begin
            Assert (Width (I) = 20 and then Height (I) = 10, File & ": size");
            for Y in 1 .. 10 loop
               for X in 1 .. 20 loop
                  Assert (Gray (Get (I, X, Y)) = Expected_Gray (X - 1, Y - 1),
                          File & ": pixel" & X'Image & Y'Image);
               end loop;
            end loop;
         end;
      end loop;
      declare
         I : constant Image := Load (Dir & "room_palette.png");
      begin
         Assert (Get (I, 1, 1) = Black and then Get (I, 2, 2) = White
                 and then Get (I, 6, 3) = White and then Get (I, 13, 5) = Black,
                 "1-bit palette image");
      end;
   end Image_Formats;

   procedure Map_Server_Worlds (Unused : in out Fixture) is
      W : constant Worlds.World := Load_World (Dir & "room.yaml");
      P : constant Worlds.World := Load_World (Dir & "room_png.yaml");
      F : constant Robot.Grids.Frame := Worlds.Frame_Of (W);
   begin
      Assert (F.Width = 20 and then F.Height = 10 and then F.Resolution = 0.1,
              "frame size and resolution");
      Assert (F.Origin = (-1.0, -0.5), "origin from the YAML file");
      Assert (Worlds.Is_Occupied (W, 0, 0), "border wall");
      Assert (not Worlds.Is_Occupied (W, 1, 1), "free cell");
      Assert (Worlds.Is_Occupied (W, 5, 7), "unknown (gray 205) is solid");
      Assert (Worlds.Is_Occupied (W, 12, 5) and then Worlds.Is_Occupied (W, 13, 4),
              "image rows count from the top, grid rows from the bottom");
      Assert (abs (Worlds.Cast (W, (-0.75, -0.05), 0.0, 5.0) - 0.95) < 1.0E-9,
              "ray to the obstacle block" & Worlds.Cast (W, (-0.75, -0.05), 0.0, 5.0)'Image);
      for I in 0 .. 19 loop
         for J in 0 .. 9 loop
            Assert (Worlds.Is_Occupied (W, I, J) = Worlds.Is_Occupied (P, I, J),
                    "PNG and PGM maps agree");
         end loop;
      end loop;
   end Map_Server_Worlds;

   procedure Wall_Worlds (Unused : in out Fixture) is
      W : constant Worlds.World := Load_World (Dir & "room.walls");
   begin
      Assert (abs (Worlds.Cast (W, (1.0, 1.5), 0.0, 8.0) - 0.9) < 1.0E-9,
              "pillar face at x = 1.9:" & Worlds.Cast (W, (1.0, 1.5), 0.0, 8.0)'Image);
      Assert (abs (Worlds.Cast (W, (1.0, 1.5), Geometry.Pi, 8.0) - 0.95) < 1.0E-9,
              "box wall face at x = 0.05");
   end Wall_Worlds;

   procedure Bad_Files (Unused : in out Fixture) is
      procedure Assert_Says (E : Ada.Exceptions.Exception_Occurrence; File, Pattern : String) is
      begin
         Assert (Contains (Ada.Exceptions.Exception_Message (E), Pattern),
                 File & ": message """ & Ada.Exceptions.Exception_Message (E)
                 & """ lacks """ & Pattern & """");
      end Assert_Says;

      procedure Check (File, Pattern : String) is
      begin
         declare
            W : constant Worlds.World := Load_World (Dir & File);
         begin
            Assert (False, File & ": accepted" & Worlds.Frame_Of (W).Width'Image);
         end;
      exception
         when E : Format_Error =>
            Assert_Says (E, File, Pattern);
      end Check;

      procedure Check_Image (File, Pattern : String) is
      begin
         declare
            I : constant Image := Load (Dir & File);
         begin
            Assert (False, File & ": accepted" & Width (I)'Image);
         end;
      exception
         when E : Format_Error =>
            Assert_Says (E, File, Pattern);
      end Check_Image;
   begin
      Check ("bad_resolution.yaml", "bad_resolution.yaml:3: expected resolution");
      Check ("missing_origin.yaml", "missing key(s): origin");
      Check ("bad.walls", "bad.walls:4: expected X2 (a number), found ""ten""");
      Check ("no_such.yaml", "no_such.yaml: cannot be opened");
      Check_Image ("bad_crc.png", "CRC mismatch");
      Check_Image ("truncated.png", "truncated");
      Check_Image ("truncated.pgm", "byte 13: truncated pixel data");
      Check_Image ("bad_header.pgm", "byte 6: expected height");
      Check_Image ("no_such.png", "no such file");
   end Bad_Files;

   procedure Corrupted_Files (Unused : in out Fixture) is
      --  Every byte of the fixtures flipped in turn (and truncations):
      --  decoding either succeeds or raises Format_Error, nothing else.
      type Name_List is array (1 .. 4) of String (1 .. 16);
      Names : constant Name_List :=
        ["room.png        ", "room_rgb.png    ", "room_palette.png", "room.pgm        "];
      Tried, Refused : Natural := 0;
   begin
      for Name of Names loop
         declare
            Good : constant Byte_Array :=
              Read_File (Dir & Ada.Strings.Fixed.Trim (Name, Ada.Strings.Right));
         begin
            for K in Good'Range loop
               for Cut in Boolean loop
                  declare
                     Bad : Byte_Array := (if Cut then Good (Good'First .. K) else Good);
                  begin
                     if not Cut then
                        Bad (K) := Bad (K) xor 16#A5#;
                     end if;
                     Tried := Tried + 1;
                     declare
                        I : constant Image :=
                          (if Bad'Length >= 8 and then Bad (Bad'First) = 137
                           then Decode_PNG (Bad, "fuzz") else Decode_PGM (Bad, "fuzz"));
                     begin
                        Assert (Width (I) > 0 and then Height (I) > 0, "a decoded image");
                     end;
                  exception
                     when Format_Error =>
                        Refused := Refused + 1;
                  end;
               end loop;
            end loop;
         end;
      end loop;
      Assert (Refused > Tried / 2, "most corruptions are detected:" & Refused'Image
              & " of" & Tried'Image);
   end Corrupted_Files;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;

      procedure Add (Name : String; Test : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("world files: " & Name, Test));
      end Add;
   begin
      Add ("CRC-32 and Adler-32", Checksums'Access);
      Add ("zlib on known streams", Zlib_Known_Streams'Access);
      Add ("PNG encode/decode round trip", PNG_Round_Trip'Access);
      Add ("PGM P5/P2 and PNG gray/RGB/palette", Image_Formats'Access);
      Add ("map-server YAML worlds", Map_Server_Worlds'Access);
      Add ("wall worlds", Wall_Worlds'Access);
      Add ("bad files give file:line or byte errors", Bad_Files'Access);
      Add ("corrupted images: Format_Error or success, never a crash",
           Corrupted_Files'Access);
      return Result;
   end Suite;

end Sancta.Simulation.Map_Files.Tests;
