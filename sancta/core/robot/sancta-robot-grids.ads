--  Regular grids over the plane: a frame (origin of the lower-left corner
--  of cell (0, 0), square cell size, columns and rows) and a Boolean
--  occupancy grid. Column I grows along X, row J along Y (ROS map
--  convention: row 0 is the bottom of the map). Everything outside a grid
--  counts as occupied.
--
--     G : Grid (W - 1, H - 1);  --  all free
--     G.Occupied (I, J) := True;
--     if Is_Occupied (G, Column (Frame_Of (G), P.X), Row (...)) then ...
with Sancta.Geometry; use Sancta.Geometry;

package Sancta.Robot.Grids
  with Pure
is

   type Frame is record
      Origin     : Point;
      --  World position of the lower-left corner of cell (0, 0).
      Resolution : Real := 0.05;
      --  Cell side, m.
      Width      : Natural := 0;
      --  Columns (along X).
      Height     : Natural := 0;
      --  Rows (along Y).
   end record;

   Far : constant := 1_000_000;
   --  Column/row numbers are clamped to -Far .. Far.

   function Floor (V : Real) return Integer
     with Inline;
   --  The integer at or below V, clamped to -Far .. Far (fast).

   function Column (F : Frame; X : Real) return Integer
     with Pre => F.Resolution > 0.0, Inline;
   --  The column holding abscissa X (may be outside 0 .. Width - 1).

   function Row (F : Frame; Y : Real) return Integer
     with Pre => F.Resolution > 0.0, Inline;

   function Contains (F : Frame; I, J : Integer) return Boolean is
     (I in 0 .. F.Width - 1 and then J in 0 .. F.Height - 1);

   function Center (F : Frame; I, J : Integer) return Point is
     ((F.Origin.X + (Real (I) + 0.5) * F.Resolution,
       F.Origin.Y + (Real (J) + 0.5) * F.Resolution));

   type Cell_Matrix is array (Integer range <>, Integer range <>) of Boolean;

   type Grid (Last_Column, Last_Row : Integer) is record
      Origin     : Point;
      Resolution : Real := 0.05;
      Occupied   : Cell_Matrix (0 .. Last_Column, 0 .. Last_Row) :=
        [others => [others => False]];
   end record;
   --  Declare with Grid (Width - 1, Height - 1).

   function Width (G : Grid) return Natural is (Natural'Max (0, G.Last_Column + 1));
   function Height (G : Grid) return Natural is (Natural'Max (0, G.Last_Row + 1));

   function Frame_Of (G : Grid) return Frame is
     ((G.Origin, G.Resolution, Width (G), Height (G)));

   function Is_Occupied (G : Grid; I, J : Integer) return Boolean is
     (not Contains (Frame_Of (G), I, J) or else G.Occupied (I, J));

   function Is_Occupied_At (G : Grid; P : Point) return Boolean is
     (Is_Occupied (G, Column (Frame_Of (G), P.X), Row (Frame_Of (G), P.Y)));

   type Segment is record
      A, B      : Point;
      Thickness : Real := 0.0;
   end record;
   --  A straight wall from A to B.

   type Segment_Array is array (Positive range <>) of Segment;

   procedure Draw (G : in out Grid; Wall : Segment);
   --  Marks occupied every cell whose centre lies closer to the wall than
   --  half its thickness plus half a cell (so a thin wall is at least one
   --  cell thick and unbroken).

   function Distance_To_Segment (P : Point; Wall : Segment) return Real;

   generic
      with procedure Occupied_Run (Row, First_Column, Last_Column : Integer);
   procedure For_Each_Occupied_Run (G : Grid);
   --  Calls Occupied_Run once for each longest horizontal run of occupied
   --  cells of G, row 0 first, each row from left to right (how a map is
   --  drawn with one rectangle a run rather than one a cell).

end Sancta.Robot.Grids;
