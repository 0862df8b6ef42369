--  Readers for TSPLIB files (Reinelt 1991): TSP and ATSP instances with
--  EDGE_WEIGHT_TYPE EUC_2D (nint), CEIL_2D, ATT (pseudo-Euclidean), GEO and
--  EXPLICIT (FULL_MATRIX, UPPER_ROW, LOWER_ROW, UPPER_DIAG_ROW,
--  LOWER_DIAG_ROW, UPPER_COL, LOWER_COL, UPPER_DIAG_COL, LOWER_DIAG_COL),
--  and TOUR files (.opt.tour). Bad files raise Format_Error "file:line:
--  reason".
--
--     P : constant Problem_Access := To_MTSP (Read ("eil51.tsp"), Robots => 5);
--
--  With Scale > 0, coordinates give real Euclidean distances in fixed point
--  (nint (Scale * d)) instead of TSPLIB's rounded integers.
with Sancta.Allocation.Problems; use Sancta.Allocation.Problems;

package Sancta.Allocation.TSPLIB is

   Max_Dimension : constant := 5_000;
   --  Larger instances are refused (an explicit, ATT or GEO matrix would
   --  exceed 200 MB; EUC_2D / CEIL_2D distances above Matrix_Limit cities
   --  are computed, but the search is not built for more).

   Max_File_Size : constant := 256 * 1024 * 1024;
   --  Bytes: larger files are refused before they are read.

   function Read
     (File : String; Scale : Long_Float := 0.0;
      Keep_Matrix_Up_To : Natural := Matrix_Limit) return Problem_Access;
   --  The instance as a problem of DIMENSION locations (one task per
   --  location, one robot). Use To_MTSP for the classic mTSP. EUC_2D and
   --  CEIL_2D instances (and any with Scale > 0) of more than
   --  Keep_Matrix_Up_To cities have computed distances (no matrix).

   function To_MTSP
     (Instance : Problem; Robots : Positive; Depot : Positive := 1;
      Min_Tasks : Natural := 1) return Problem_Access
     with Pre => Instance.Locations >= 2;
   --  m salesmen on closed tours from Depot; every other node is a task
   --  (task T at location T + 1 when Depot = 1); each salesman visits at
   --  least Min_Tasks cities.

   function Read_Tour (File : String) return Location_Array;
   --  The node sequence of a TOUR_SECTION.

   function Tour_Length (Instance : Problem; Tour : Location_Array) return Cost;
   --  Closed tour length over node numbers.

end Sancta.Allocation.TSPLIB;
