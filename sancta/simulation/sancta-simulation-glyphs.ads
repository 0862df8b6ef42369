--  A 5 x 7 pixel font to write labels into raster pictures (the PNG
--  renderings): digits, letters (lower case drawn as upper case), space
--  and - _ . , : > < ( ) / + = % # ? '; other characters are drawn as '?'.
--
--     Glyphs.Draw_Text (Img, X => 10, Y => 4, Text => "r1: 7 tasks", Color => Black);
with Sancta.Simulation.Raster_Images;

package Sancta.Simulation.Glyphs is

   Glyph_Width  : constant := 5;
   Glyph_Height : constant := 7;
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
