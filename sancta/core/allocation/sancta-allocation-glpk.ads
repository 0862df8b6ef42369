--  A thin binding to the parts of GLPK (the GNU Linear Programming Kit,
--  Debian's libglpk-dev) that the branch-and-cut solver uses: an LP with
--  rows added and deleted on the fly, bounds changed between solves, the
--  primal simplex and the dual simplex warm-started from the last basis,
--  primal values, duals and reduced costs. Indices are 1-based as in GLPK.
--
--     LP : constant Problem := Create_Problem;
--     Set_Minimize (LP);  First := Add_Columns (LP, 3);  ...
--     Status := Simplex (LP, Dual => True, Time_Limit_Ms => 1000);
--     X := Column_Value (LP, 1);
--     Delete_Problem (LP);
with Interfaces.C;
with System;

package Sancta.Allocation.GLPK is

   type Problem is private;
   No_Problem : constant Problem;

   type Int_Array is array (Positive range <>) of Interfaces.C.int
     with Convention => C;
   type Real_Array is array (Positive range <>) of Interfaces.C.double
     with Convention => C;

   function Create_Problem return Problem;
   procedure Delete_Problem (LP : in out Problem);
   procedure Set_Minimize (LP : Problem);

   function Add_Rows (LP : Problem; Count : Positive) return Positive;
   function Add_Columns (LP : Problem; Count : Positive) return Positive;
   --  The index of the first new row / column.

   procedure Delete_Rows (LP : Problem; Rows : Int_Array)
     with Pre => Rows'First = 1;
   --  Rows (1 .. Rows'Last) deleted (the rows after them are renumbered).

   function Row_Count (LP : Problem) return Natural;

   procedure Set_Row_Fixed (LP : Problem; Row : Positive; Value : Long_Float);
   procedure Set_Row_Lower (LP : Problem; Row : Positive; Value : Long_Float);
   procedure Set_Column_Bounds (LP : Problem; Column : Positive; Lower, Upper : Long_Float);
   procedure Set_Objective (LP : Problem; Column : Positive; Coefficient : Long_Float);

   procedure Set_Column
     (LP : Problem; Column : Positive; Rows : Int_Array; Values : Real_Array)
     with Pre => Rows'First = 1 and then Values'First = 1 and then Rows'Last = Values'Last;
   --  The coefficients of Column (all others 0).

   procedure Set_Row (LP : Problem; Row : Positive; Columns : Int_Array; Values : Real_Array)
     with Pre => Columns'First = 1 and then Values'First = 1
                 and then Columns'Last = Values'Last;
   --  The coefficients of Row (all others 0).

   type Status is (Optimal, Infeasible, Unbounded, Limit_Reached, Above_Limit, Failed);
   --  Limit_Reached: the iteration or time limit stopped it (the dual
   --  simplex's objective is then a lower bound on the optimum).
   --  Above_Limit: the dual simplex's objective passed Objective_Limit (the
   --  optimum is above it). Failed: numerical trouble.

   function Simplex
     (LP              : Problem;
      Dual            : Boolean;
      Time_Limit_Ms   : Natural := 0;
      Iteration_Limit : Natural := 0;
      Objective_Limit : Long_Float := Long_Float'Last) return Status;
   --  Solves from the current basis (dual simplex after bound changes and
   --  new cuts; primal at the start). 0 = no time / iteration limit.

   function Column_Count (LP : Problem) return Natural;

   type Basis is array (Positive range <>) of Interfaces.C.int;
   --  The status of every row, then of every column.

   function Current_Basis (LP : Problem) return Basis;
   procedure Restore_Basis (LP : Problem; B : Basis)
     with Pre => B'First = 1 and then B'Length = Row_Count (LP) + Column_Count (LP);
   --  The basis of an earlier Current_Basis (same rows and columns).

   function Objective_Value (LP : Problem) return Long_Float;
   function Column_Value (LP : Problem; Column : Positive) return Long_Float;
   function Reduced_Cost (LP : Problem; Column : Positive) return Long_Float;
   function Row_Dual (LP : Problem; Row : Positive) return Long_Float;
   function Row_Is_Basic (LP : Problem; Row : Positive) return Boolean;
   --  Basic: the cut is slack (a candidate for deletion).

private

   type Problem is new System.Address;
   No_Problem : constant Problem := Problem (System.Null_Address);

end Sancta.Allocation.GLPK;
