--  A 5 x 7 pixel font to write labels into raster pictures (the PNG
--  renderings; 5 x 9 with the tails of g j p q y): digits, letters
--  (lower case with a 5-row x-height), space and - _ . , : > < ( ) / + =
--  % # ? '; other characters are drawn as '?'.
--
--     Glyphs.Draw_Text (Img, X => 10, Y => 4, Text => "r1: 7 tasks", Color => Black);
with Sancta.Simulation.Raster_Images;

package Sancta.Simulation.Glyphs is

   Glyph_Width  : constant := 5;
   Cap_Height   : constant := 7;
   --  Rows of a capital letter or a digit, from the top of the cell.
   Glyph_Height : constant := Cap_Height + 2;
   --  Rows of the cell: two more below the base line for g j p q y.
   Advance      : constant := Glyph_Width + 1;
   --  Pixels from one character to the next.

   function Is_Inked (C : Character; Column, Row : Positive) return Boolean
     with Pre => Column <= Glyph_Width and then Row <= Glyph_Height;
   --  Whether pixel (Column, Row) of C's glyph is set; row 1 is the top.

   function Text_Width (Text : String) return Natural is (Text'Length * Advance);

   procedure Draw_Text
     (Img   : in out Raster_Images.Image;
      X, Y  : Integer;
      Text  : String;
      Color : Raster_Images.Color;
      Halo  : Boolean := True);
   --  Text with its top left corner at pixel (X, Y), clipped to the image;
   --  Halo: a one-pixel white outline, legible over lines and walls.

end Sancta.Simulation.Glyphs;
