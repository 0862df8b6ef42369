with Ada.Characters.Handling;
with Ada.Directories;
with Ada.Streams.Stream_IO;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Strings.Fixed;
with Sancta.Geometry;

package body Sancta.Allocation.TSPLIB is

   use Ada.Numerics.Long_Elementary_Functions;
   use type Sancta.Geometry.Real;

   --  A cursor over the whole file held in memory.
   type Text_Access is access String;

   type Scanner is record
      Name : Text_Access;
      Text : Text_Access;
      Pos  : Positive := 1;
      Line : Positive := 1;
   end record;

   procedure Fail (S : Scanner; Reason : String) with No_Return;

   procedure Fail (S : Scanner; Reason : String) is
   begin
      raise Format_Error with S.Name.all & ":" & Ada.Strings.Fixed.Trim (S.Line'Image,
        Ada.Strings.Left) & ": " & Reason;
   end Fail;

   function Load (File : String) return Scanner is
   begin
      if not Ada.Directories.Exists (File) then
         raise Format_Error with File & ":1: no such file";
      end if;
      if Ada.Directories."/=" (Ada.Directories.Kind (File), Ada.Directories.Ordinary_File) then
         raise Format_Error with File & ":1: not a regular file";
      elsif Ada.Directories."/=" (Ada.Directories.Size (File), 0)
        and then Long_Long_Integer (Ada.Directories.Size (File)) > Max_File_Size
      then
         raise Format_Error with File & ":1: file of"
           & Ada.Directories.File_Size'Image (Ada.Directories.Size (File))
           & " bytes exceeds the limit of" & Max_File_Size'Image;
      end if;
      declare
         --  Read in chunks onto the heap (a whole-file buffer on the stack
         --  overflows it for files of a few megabytes).
         use Ada.Streams;
         Size  : constant Natural := Natural (Ada.Directories.Size (File));
         F     : Stream_IO.File_Type;
         Chunk : Stream_Element_Array (1 .. 65_536);
         Last  : Stream_Element_Offset;
         Next  : Positive := 1;
         S     : Scanner;
      begin
         S.Name := new String'(File);
         S.Text := new String (1 .. Size);
         Stream_IO.Open (F, Stream_IO.In_File, File);
         while Next <= Size and then not Stream_IO.End_Of_File (F) loop
            Stream_IO.Read (F, Chunk, Last);
            for K in 1 .. Last loop
               exit when Next > Size;
               S.Text (Next) := Character'Val (Chunk (K));
               Next := Next + 1;
            end loop;
         end loop;
         Stream_IO.Close (F);
         if Next <= Size then
            S.Text := new String'(S.Text (1 .. Next - 1));
         end if;
         return S;
      end;
   end Load;

   function At_End (S : Scanner) return Boolean is (S.Pos > S.Text'Last);

   function Is_Space (C : Character) return Boolean is
     (C = ' ' or else C = ASCII.HT or else C = ASCII.CR or else C = ASCII.LF);

   procedure Skip_Blanks (S : in out Scanner) is
   begin
      while not At_End (S) and then Is_Space (S.Text (S.Pos)) loop
         if S.Text (S.Pos) = ASCII.LF then
            S.Line := S.Line + 1;
         end if;
         S.Pos := S.Pos + 1;
      end loop;
   end Skip_Blanks;

   function Next_Token (S : in out Scanner) return String is
      First : Positive;
   begin
      Skip_Blanks (S);
      First := S.Pos;
      while not At_End (S) and then not Is_Space (S.Text (S.Pos)) loop
         S.Pos := S.Pos + 1;
      end loop;
      return S.Text (First .. S.Pos - 1);
   end Next_Token;

   function Rest_Of_Line (S : in out Scanner) return String is
      First : constant Positive := S.Pos;
   begin
      while not At_End (S) and then S.Text (S.Pos) /= ASCII.LF loop
         S.Pos := S.Pos + 1;
      end loop;
      return Ada.Strings.Fixed.Trim (S.Text (First .. S.Pos - 1), Ada.Strings.Both);
   end Rest_Of_Line;

   function Next_Real (S : in out Scanner; What : String) return Long_Float is
      Tok : constant String := Next_Token (S);
   begin
      if Tok = "" then
         Fail (S, "end of file while reading " & What);
      end if;
      declare
         Value : Long_Float;
      begin
         begin
            Value := Long_Float'Value (Tok);
         exception
            when Constraint_Error =>
               Fail (S, "expected a number for " & What & ", found '" & Tok & "'");
         end;
         if not Value'Valid or else abs Value > 1.0E9 then
            --  Distances are whole numbers: squares must stay finite.
            Fail (S, What & " '" & Tok & "' is not a finite number within +/-1e9");
         end if;
         return Value;
      end;
   end Next_Real;

   function Next_Integer (S : in out Scanner; What : String) return Long_Long_Integer is
      Tok : constant String := Next_Token (S);
   begin
      if Tok = "" then
         Fail (S, "end of file while reading " & What);
      end if;
      return Long_Long_Integer'Value (Tok);
   exception
      when Constraint_Error =>
         Fail (S, "expected an integer for " & What & ", found '" & Tok & "'");
   end Next_Integer;

   function Upper (X : String) return String renames Ada.Characters.Handling.To_Upper;

   --  A header line "KEY : VALUE" or "KEY: VALUE" or a section keyword.
   procedure Header (S : in out Scanner; Key : out Text_Access; Value : out Text_Access) is
      Line : constant String := Rest_Of_Line (S);
      Colon : constant Natural := Ada.Strings.Fixed.Index (Line, ":");
   begin
      if Colon = 0 then
         Key := new String'(Upper (Line));
         Value := new String'("");
      else
         Key := new String'(Upper (Ada.Strings.Fixed.Trim
                              (Line (Line'First .. Colon - 1), Ada.Strings.Both)));
         Value := new String'(Ada.Strings.Fixed.Trim
                                (Line (Colon + 1 .. Line'Last), Ada.Strings.Both));
      end if;
   end Header;

   function Nint (X : Long_Float) return Cost is (Cost (Long_Float'Floor (X + 0.5)));

   function Geo_Radians (X : Long_Float) return Long_Float is
      Pi_TSPLIB : constant := 3.141592;
      Deg : constant Long_Float := Long_Float'Truncation (X);
      Min : constant Long_Float := X - Deg;
   begin
      return Pi_TSPLIB * (Deg + 5.0 * Min / 3.0) / 180.0;
   end Geo_Radians;

   function Read
     (File : String; Scale : Long_Float := 0.0;
      Keep_Matrix_Up_To : Natural := Matrix_Limit) return Problem_Access
   is
      S          : Scanner := Load (File);
      Dimension  : Natural := 0;
      Kind       : Text_Access := new String'("");
      Weight_Type : Text_Access := new String'("");
      Format     : Text_Access := new String'("FULL_MATRIX");
      P          : Problem_Access;
      Name       : Text_Access := new String'("");
      Got_Weights : Boolean := False;

      procedure Need_Dimension is
      begin
         if Dimension = 0 then
            Fail (S, "section before DIMENSION");
         end if;
         if P = null then
            P := Create (Dimension, Dimension, 1);
         end if;
      end Need_Dimension;

      procedure Read_Coordinates is
         Points : Point_Array (1 .. Dimension);
         Seen   : Boolean_Array (1 .. Dimension) := [others => False];
      begin
         for K in 1 .. Dimension loop
            declare
               Id : constant Long_Long_Integer := Next_Integer (S, "node number");
            begin
               if Id not in 1 .. Long_Long_Integer (Dimension) then
                  Fail (S, "node number" & Id'Image & " outside 1 .." & Dimension'Image);
               elsif Seen (Positive (Id)) then
                  Fail (S, "node" & Id'Image & " given twice");
               end if;
               Seen (Positive (Id)) := True;
               Points (Positive (Id)).X := Sancta.Geometry.Real (Next_Real (S, "x"));
               Points (Positive (Id)).Y := Sancta.Geometry.Real (Next_Real (S, "y"));
            end;
         end loop;
         P.Coordinates := Points;
         P.Has_Coordinates := True;
         declare
            WT : constant String := Weight_Type.all;
         begin
            if (WT = "EUC_2D" or else WT = "CEIL_2D")
              and then (Scale > 0.0 or else Dimension > Keep_Matrix_Up_To)
            then
               Set_Euclidean
                 (P.all, Points, (if Scale > 0.0 then Scale else 1.0),
                  Rule => (if WT = "CEIL_2D" and then Scale <= 0.0 then Euclidean_Ceiling
                           else Euclidean_Nearest),
                  Keep_Matrix_Up_To => Keep_Matrix_Up_To);
            elsif WT = "EUC_2D" or else WT = "CEIL_2D" then
               for A in 1 .. Dimension loop
                  for B in 1 .. Dimension loop
                     declare
                        DX : constant Long_Float := Long_Float (Points (A).X - Points (B).X);
                        DY : constant Long_Float := Long_Float (Points (A).Y - Points (B).Y);
                        D  : constant Long_Float := Sqrt (DX * DX + DY * DY);
                     begin
                        Set_Distance
                          (P.all, A, B,
                           (if WT = "CEIL_2D" then Cost (Long_Float'Ceiling (D)) else Nint (D)));
                     end;
                  end loop;
               end loop;
            elsif WT = "ATT" then
               for A in 1 .. Dimension loop
                  for B in 1 .. Dimension loop
                     declare
                        DX : constant Long_Float := Long_Float (Points (A).X - Points (B).X);
                        DY : constant Long_Float := Long_Float (Points (A).Y - Points (B).Y);
                        R  : constant Long_Float := Sqrt ((DX * DX + DY * DY) / 10.0);
                        T  : constant Cost := Nint (R);
                     begin
                        Set_Distance (P.all, A, B, (if Long_Float (T) < R then T + 1 else T));
                     end;
                  end loop;
               end loop;
            elsif WT = "GEO" then
               for A in 1 .. Dimension loop
                  for B in 1 .. Dimension loop
                     if A /= B then
                        declare
                           RRR : constant := 6378.388;
                           LatA : constant Long_Float := Geo_Radians (Long_Float (Points (A).X));
                           LonA : constant Long_Float := Geo_Radians (Long_Float (Points (A).Y));
                           LatB : constant Long_Float := Geo_Radians (Long_Float (Points (B).X));
                           LonB : constant Long_Float := Geo_Radians (Long_Float (Points (B).Y));
                           Q1 : constant Long_Float := Cos (LonA - LonB);
                           Q2 : constant Long_Float := Cos (LatA - LatB);
                           Q3 : constant Long_Float := Cos (LatA + LatB);
                           Arg : constant Long_Float :=
                             Long_Float'Max (-1.0, Long_Float'Min
                               (1.0, 0.5 * ((1.0 + Q1) * Q2 - (1.0 - Q1) * Q3)));
                        begin
                           Set_Distance
                             (P.all, A, B, Cost (Long_Float'Truncation (RRR * Arccos (Arg) + 1.0)));
                        end;
                     end if;
                  end loop;
               end loop;
            elsif WT = "EXPLICIT" then
               null;  --  display coordinates only
            else
               Fail (S, "unsupported EDGE_WEIGHT_TYPE '" & WT & "'");
            end if;
         end;
         Got_Weights := Got_Weights or else Weight_Type.all /= "EXPLICIT";
      end Read_Coordinates;

      procedure Read_Weights is
         F : constant String := Format.all;
         N : constant Positive := Dimension;

         procedure Put (A, B : Positive) is
            W : constant Long_Long_Integer := Next_Integer (S, "edge weight");
         begin
            if W < 0 or else W >= Infinity then
               Fail (S, "edge weight" & W'Image & " out of range");
            end if;
            if A /= B then
               Set_Distance (P.all, A, B, W);
            end if;
         end Put;

         procedure Put_Symmetric (A, B : Positive) is
         begin
            Put (A, B);
            Set_Distance (P.all, B, A, Distance (P.all, A, B));
         end Put_Symmetric;
      begin
         if Weight_Type.all /= "EXPLICIT" then
            Fail (S, "EDGE_WEIGHT_SECTION needs EDGE_WEIGHT_TYPE: EXPLICIT");
         end if;
         if F = "FULL_MATRIX" then
            for A in 1 .. N loop
               for B in 1 .. N loop
                  Put (A, B);
               end loop;
            end loop;
         elsif F = "UPPER_ROW" or else F = "LOWER_COL" then
            for A in 1 .. N loop
               for B in A + 1 .. N loop
                  Put_Symmetric (A, B);
               end loop;
            end loop;
         elsif F = "LOWER_ROW" or else F = "UPPER_COL" then
            for A in 1 .. N loop
               for B in 1 .. A - 1 loop
                  Put_Symmetric (A, B);
               end loop;
            end loop;
         elsif F = "UPPER_DIAG_ROW" or else F = "LOWER_DIAG_COL" then
            for A in 1 .. N loop
               for B in A .. N loop
                  Put_Symmetric (A, B);
               end loop;
            end loop;
         elsif F = "LOWER_DIAG_ROW" or else F = "UPPER_DIAG_COL" then
            for A in 1 .. N loop
               for B in 1 .. A loop
                  Put_Symmetric (A, B);
               end loop;
            end loop;
         else
            Fail (S, "unsupported EDGE_WEIGHT_FORMAT '" & F & "'");
         end if;
         Got_Weights := True;
      end Read_Weights;

      Key, Value : Text_Access;
   begin
      loop
         Skip_Blanks (S);
         exit when At_End (S);
         Header (S, Key, Value);
         declare
            K : constant String := Key.all;
            V : constant String := Value.all;
         begin
            if K = "EOF" then
               exit;
            elsif K = "NAME" then
               Name := new String'(V);
            elsif K = "TYPE" then
               Kind := new String'(Upper (V));
               if Kind.all not in "TSP" | "ATSP" then
                  Fail (S, "TYPE '" & V & "' is not TSP or ATSP");
               end if;
            elsif K = "COMMENT" or else K = "DISPLAY_DATA_TYPE" or else K = "NODE_COORD_TYPE"
            then
               null;
            elsif K = "DIMENSION" then
               begin
                  Dimension := Natural'Value (V);
               exception
                  when Constraint_Error =>
                     Fail (S, "DIMENSION '" & V & "' is not a count");
               end;
               if Dimension < 2 or else Dimension > Max_Dimension then
                  Fail (S, "DIMENSION" & Dimension'Image & " outside 2 .." & Max_Dimension'Image
                        & " (full distance matrices are held in memory)");
               end if;
            elsif K = "EDGE_WEIGHT_TYPE" then
               Weight_Type := new String'(Upper (V));
            elsif K = "EDGE_WEIGHT_FORMAT" then
               Format := new String'(Upper (V));
            elsif K = "NODE_COORD_SECTION" then
               Need_Dimension;
               Read_Coordinates;
            elsif K = "DISPLAY_DATA_SECTION" then
               Need_Dimension;
               declare
                  Saved : constant Text_Access := Weight_Type;
               begin
                  Weight_Type := new String'("EXPLICIT");
                  Read_Coordinates;
                  Weight_Type := Saved;
               end;
            elsif K = "EDGE_WEIGHT_SECTION" then
               Need_Dimension;
               Read_Weights;
            else
               Fail (S, "unknown keyword '" & K & "'");
            end if;
         end;
      end loop;
      if Dimension = 0 or else P = null then
         Fail (S, "no DIMENSION or no data section");
      elsif not Got_Weights then
         Fail (S, "no distances (EDGE_WEIGHT_SECTION or NODE_COORD_SECTION)");
      end if;
      P.Name := [others => ' '];
      declare
         N : constant String := Name.all;
         L : constant Natural := Natural'Min (N'Length, P.Name'Length);
      begin
         P.Name (1 .. L) := N (N'First .. N'First + L - 1);
      end;
      Update_Symmetry (P.all);
      P.Scale := (if Scale > 0.0 then Scale else 1.0);
      return P;
   end Read;

   function To_MTSP
     (Instance : Problem; Robots : Positive; Depot : Positive := 1;
      Min_Tasks : Natural := 1) return Problem_Access
   is
      N : constant Positive := Instance.Locations;
      P : constant Problem_Access := Create (N, N - 1, Robots);
      T : Natural := 0;
   begin
      Copy_Distances (Instance, P.all);
      P.Name := Instance.Name;
      for L in 1 .. N loop
         if L /= Depot then
            T := T + 1;
            Set_Task (P.all, T, L);
         end if;
      end loop;
      for R in 1 .. Robots loop
         Set_Robot (P.all, R, Start => Depot, Closed => True);
      end loop;
      P.Min_Tasks := Min_Tasks;
      return P;
   end To_MTSP;

   function Read_Tour (File : String) return Location_Array is
      S : Scanner := Load (File);
      Dimension : Natural := 0;
      Key, Value : Text_Access;
   begin
      loop
         Skip_Blanks (S);
         if At_End (S) then
            Fail (S, "no TOUR_SECTION");
         end if;
         Header (S, Key, Value);
         declare
            K : constant String := Key.all;
         begin
            if K = "DIMENSION" then
               begin
                  Dimension := Natural'Value (Value.all);
               exception
                  when Constraint_Error =>
                     Fail (S, "DIMENSION '" & Value.all & "' is not a count");
               end;
            elsif K = "TYPE" then
               if Upper (Value.all) /= "TOUR" then
                  Fail (S, "TYPE '" & Value.all & "' is not TOUR");
               end if;
            elsif K = "TOUR_SECTION" then
               exit;
            elsif K in "NAME" | "COMMENT" then
               null;
            else
               Fail (S, "unknown keyword '" & K & "'");
            end if;
         end;
      end loop;
      if Dimension = 0 then
         Fail (S, "TOUR_SECTION before DIMENSION");
      end if;
      declare
         Tour : Location_Array (1 .. Dimension);
         Seen : Boolean_Array (1 .. Dimension) := [others => False];
      begin
         for K in 1 .. Dimension loop
            declare
               Id : constant Long_Long_Integer := Next_Integer (S, "tour node");
            begin
               if Id not in 1 .. Long_Long_Integer (Dimension) then
                  Fail (S, "tour node" & Id'Image & " outside 1 .." & Dimension'Image);
               elsif Seen (Positive (Id)) then
                  Fail (S, "tour node" & Id'Image & " repeated");
               end if;
               Seen (Positive (Id)) := True;
               Tour (K) := Positive (Id);
            end;
         end loop;
         return Tour;
      end;
   end Read_Tour;

   function Tour_Length (Instance : Problem; Tour : Location_Array) return Cost is
      L : Cost := 0;
   begin
      for K in Tour'Range loop
         L := L + Distance
           (Instance, Tour (K), Tour (if K = Tour'Last then Tour'First else K + 1));
      end loop;
      return L;
   end Tour_Length;

end Sancta.Allocation.TSPLIB;
