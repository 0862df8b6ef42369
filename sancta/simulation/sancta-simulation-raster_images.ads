--  Raster images for maps and rendering: an RGB image held on the heap,
--  read from PGM (P5 binary, P2 ASCII) and PNG (every standard colour type
--  and bit depth, not interlaced; zlib decompresses), written as PNG
--  (compressed by zlib) and PGM (P5).
--  Pixel (1, 1) is the top-left corner.
--
--     Img : Image := Load ("map.png");
--     Set (Img, 10, 20, (255, 0, 0));
--     Save_PNG (Img, "out.png");
with Ada.Finalization;
with Sancta.Simulation.Zlib;

package Sancta.Simulation.Raster_Images is

   subtype Byte is Zlib.Byte;

   type Color is record
      R, G, B : Byte := 0;
   end record;

   Black : constant Color := (0, 0, 0);
   White : constant Color := (255, 255, 255);

   function Gray (C : Color) return Byte is
     (Byte ((Natural (C.R) + Natural (C.G) + Natural (C.B)) / 3));

   type Image is new Ada.Finalization.Controlled with private;
   --  Copies are deep. The default image is 0 x 0.

   Max_Side : constant := 30_000;
   Max_Pixels : constant := 40_000_000;
   --  Larger images are refused (as malformed) rather than allocated.

   function Create (Width, Height : Natural; Fill : Color := White) return Image
     with Pre => Width <= Max_Side and then Height <= Max_Side
                 and then Width * Height <= Max_Pixels;

   function Width (This : Image) return Natural;
   function Height (This : Image) return Natural;

   function Get (This : Image; X, Y : Positive) return Color
     with Pre => X <= Width (This) and then Y <= Height (This);

   procedure Set (This : in out Image; X, Y : Integer; C : Color);
   --  Points outside the image are ignored (clipping for drawing).

   function Load (File_Name : String) return Image;
   --  A PGM or PNG file, recognised by its first bytes. Format_Error
   --  ("file: byte N: reason") when it is neither or is malformed; also
   --  when it cannot be read.

   function Decode_PNG (Data : Zlib.Byte_Array; Name : String) return Image;
   function Decode_PGM (Data : Zlib.Byte_Array; Name : String) return Image;
   --  Name only serves the error messages.

   function Encode_PNG (This : Image) return Zlib.Byte_Array;

   procedure Save_PNG (This : Image; File_Name : String);
   procedure Save_PGM (This : Image; File_Name : String);
   --  Gray levels (mean of the channels), binary P5.

   function Read_File (File_Name : String) return Zlib.Byte_Array;
   --  The whole file; Format_Error when it cannot be read.

private

   type Pixel_Matrix is array (Positive range <>, Positive range <>) of Color;
   type Pixel_Access is access Pixel_Matrix;

   type Image is new Ada.Finalization.Controlled with record
      Pixels : Pixel_Access;
      --  (Row, Column).
   end record;

   overriding procedure Adjust (This : in out Image);
   overriding procedure Finalize (This : in out Image);

end Sancta.Simulation.Raster_Images;
