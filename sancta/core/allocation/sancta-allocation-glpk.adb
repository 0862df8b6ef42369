package body Sancta.Allocation.GLPK is

   use Interfaces.C;

   GLP_MIN : constant := 1;
   GLP_LO  : constant := 2;
   GLP_DB  : constant := 4;
   GLP_FX  : constant := 5;
   GLP_BS  : constant := 1;
   GLP_OPT : constant := 5;
   GLP_NOFEAS : constant := 4;
   GLP_UNBND  : constant := 6;
   GLP_MSG_OFF : constant := 0;
   GLP_PRIMAL : constant := 1;
   GLP_DUALP  : constant := 2;
   GLP_EOBJUL : constant := 16#07#;
   GLP_EITLIM : constant := 16#08#;
   GLP_ETMLIM : constant := 16#09#;

   type Double_Reserve is array (1 .. 33) of double with Convention => C;
   type Simplex_Parameters is record
      Msg_Lev, Meth, Pricing, R_Test : int;
      Tol_Bnd, Tol_Dj, Tol_Piv, Obj_Ll, Obj_Ul : double;
      It_Lim, Tm_Lim, Out_Frq, Out_Dly, Presolve, Excl, Shift, Aorn : int;
      Reserved : Double_Reserve;
   end record with Convention => C;
   --  glp_smcp of GLPK 4.65 / 5.0 (glpk.h).

   function glp_create_prob return Problem with Import, Convention => C;
   procedure glp_delete_prob (LP : Problem) with Import, Convention => C;
   procedure glp_set_obj_dir (LP : Problem; Dir : int) with Import, Convention => C;
   function glp_add_rows (LP : Problem; N : int) return int with Import, Convention => C;
   function glp_add_cols (LP : Problem; N : int) return int with Import, Convention => C;
   procedure glp_del_rows (LP : Problem; N : int; Num : Int_Array)
     with Import, Convention => C;
   function glp_get_num_rows (LP : Problem) return int with Import, Convention => C;
   procedure glp_set_row_bnds (LP : Problem; I : int; Kind : int; Lb, Ub : double)
     with Import, Convention => C;
   procedure glp_set_col_bnds (LP : Problem; J : int; Kind : int; Lb, Ub : double)
     with Import, Convention => C;
   procedure glp_set_obj_coef (LP : Problem; J : int; Coef : double)
     with Import, Convention => C;
   procedure glp_set_mat_row (LP : Problem; I : int; Len : int; Ind : Int_Array;
                              Val : Real_Array)
     with Import, Convention => C;
   procedure glp_set_mat_col (LP : Problem; J : int; Len : int; Ind : Int_Array;
                              Val : Real_Array)
     with Import, Convention => C;
   procedure glp_init_smcp (Parm : out Simplex_Parameters) with Import, Convention => C;
   function glp_simplex (LP : Problem; Parm : Simplex_Parameters) return int
     with Import, Convention => C;
   function glp_get_status (LP : Problem) return int with Import, Convention => C;
   function glp_get_obj_val (LP : Problem) return double with Import, Convention => C;
   function glp_get_col_prim (LP : Problem; J : int) return double
     with Import, Convention => C;
   function glp_get_col_dual (LP : Problem; J : int) return double
     with Import, Convention => C;
   function glp_get_row_dual (LP : Problem; I : int) return double
     with Import, Convention => C;
   function glp_get_row_stat (LP : Problem; I : int) return int
     with Import, Convention => C;
   function glp_get_num_cols (LP : Problem) return int with Import, Convention => C;
   function glp_get_col_stat (LP : Problem; J : int) return int
     with Import, Convention => C;
   procedure glp_set_row_stat (LP : Problem; I : int; Stat : int)
     with Import, Convention => C;
   procedure glp_set_col_stat (LP : Problem; J : int; Stat : int)
     with Import, Convention => C;
   function glp_term_out (Flag : int) return int with Import, Convention => C;

   function Create_Problem return Problem is
      Previous : constant int := glp_term_out (0);
      pragma Unreferenced (Previous);
   begin
      return glp_create_prob;
   end Create_Problem;

   procedure Delete_Problem (LP : in out Problem) is
   begin
      if LP /= No_Problem then
         glp_delete_prob (LP);
         LP := No_Problem;
      end if;
   end Delete_Problem;

   procedure Set_Minimize (LP : Problem) is
   begin
      glp_set_obj_dir (LP, GLP_MIN);
   end Set_Minimize;

   function Add_Rows (LP : Problem; Count : Positive) return Positive is
     (Positive (glp_add_rows (LP, int (Count))));

   function Add_Columns (LP : Problem; Count : Positive) return Positive is
     (Positive (glp_add_cols (LP, int (Count))));

   function Padded (A : Int_Array) return Int_Array is ([1 => 0] & A);
   function Padded (A : Real_Array) return Real_Array is ([1 => 0.0] & A);
   --  GLPK reads ind[1 .. len] and val[1 .. len]: element 0 is unused.

   procedure Delete_Rows (LP : Problem; Rows : Int_Array) is
   begin
      glp_del_rows (LP, int (Rows'Length), Padded (Rows));
   end Delete_Rows;

   function Row_Count (LP : Problem) return Natural is (Natural (glp_get_num_rows (LP)));

   procedure Set_Row_Fixed (LP : Problem; Row : Positive; Value : Long_Float) is
   begin
      glp_set_row_bnds (LP, int (Row), GLP_FX, double (Value), double (Value));
   end Set_Row_Fixed;

   procedure Set_Row_Lower (LP : Problem; Row : Positive; Value : Long_Float) is
   begin
      glp_set_row_bnds (LP, int (Row), GLP_LO, double (Value), 0.0);
   end Set_Row_Lower;

   procedure Set_Column_Bounds (LP : Problem; Column : Positive; Lower, Upper : Long_Float) is
   begin
      glp_set_col_bnds (LP, int (Column), (if Lower = Upper then GLP_FX else GLP_DB),
                        double (Lower), double (Upper));
   end Set_Column_Bounds;

   procedure Set_Objective (LP : Problem; Column : Positive; Coefficient : Long_Float) is
   begin
      glp_set_obj_coef (LP, int (Column), double (Coefficient));
   end Set_Objective;

   procedure Set_Row (LP : Problem; Row : Positive; Columns : Int_Array; Values : Real_Array) is
   begin
      glp_set_mat_row (LP, int (Row), int (Columns'Length), Padded (Columns), Padded (Values));
   end Set_Row;

   procedure Set_Column
     (LP : Problem; Column : Positive; Rows : Int_Array; Values : Real_Array) is
   begin
      glp_set_mat_col (LP, int (Column), int (Rows'Length), Padded (Rows), Padded (Values));
   end Set_Column;

   function Simplex
     (LP              : Problem;
      Dual            : Boolean;
      Time_Limit_Ms   : Natural := 0;
      Iteration_Limit : Natural := 0;
      Objective_Limit : Long_Float := Long_Float'Last) return Status
   is
      Parm : Simplex_Parameters;
      Code : int;
   begin
      glp_init_smcp (Parm);
      Parm.Msg_Lev := GLP_MSG_OFF;
      Parm.Meth := (if Dual then GLP_DUALP else GLP_PRIMAL);
      if Time_Limit_Ms > 0 then
         Parm.Tm_Lim := int (Time_Limit_Ms);
      end if;
      if Iteration_Limit > 0 then
         Parm.It_Lim := int (Iteration_Limit);
      end if;
      if Objective_Limit < Long_Float'Last then
         Parm.Obj_Ul := double (Objective_Limit);
      end if;
      Code := glp_simplex (LP, Parm);
      case Code is
         when 0 => null;
         when GLP_EITLIM | GLP_ETMLIM => return Limit_Reached;
         when GLP_EOBJUL => return Above_Limit;
         when others => return Failed;
      end case;
      case glp_get_status (LP) is
         when GLP_OPT => return Optimal;
         when GLP_NOFEAS => return Infeasible;
         when GLP_UNBND => return Unbounded;
         when others => return Failed;
      end case;
   end Simplex;

   function Objective_Value (LP : Problem) return Long_Float is
     (Long_Float (glp_get_obj_val (LP)));
   function Column_Value (LP : Problem; Column : Positive) return Long_Float is
     (Long_Float (glp_get_col_prim (LP, int (Column))));
   function Reduced_Cost (LP : Problem; Column : Positive) return Long_Float is
     (Long_Float (glp_get_col_dual (LP, int (Column))));
   function Row_Dual (LP : Problem; Row : Positive) return Long_Float is
     (Long_Float (glp_get_row_dual (LP, int (Row))));
   function Row_Is_Basic (LP : Problem; Row : Positive) return Boolean is
     (glp_get_row_stat (LP, int (Row)) = GLP_BS);

   function Column_Count (LP : Problem) return Natural is (Natural (glp_get_num_cols (LP)));

   function Current_Basis (LP : Problem) return Basis is
      Rows : constant Natural := Row_Count (LP);
      Columns : constant Natural := Column_Count (LP);
   begin
      return B : Basis (1 .. Rows + Columns) do
         for I in 1 .. Rows loop
            B (I) := glp_get_row_stat (LP, int (I));
         end loop;
         for J in 1 .. Columns loop
            B (Rows + J) := glp_get_col_stat (LP, int (J));
         end loop;
      end return;
   end Current_Basis;

   procedure Restore_Basis (LP : Problem; B : Basis) is
      Rows : constant Natural := Row_Count (LP);
   begin
      for I in 1 .. Rows loop
         glp_set_row_stat (LP, int (I), B (I));
      end loop;
      for J in Rows + 1 .. B'Last loop
         glp_set_col_stat (LP, int (J - Rows), B (J));
      end loop;
   end Restore_Basis;

end Sancta.Allocation.GLPK;
