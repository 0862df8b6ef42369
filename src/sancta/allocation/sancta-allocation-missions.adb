with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Directories;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Input_Sources.File;
with Sax.Attributes;
with Sax.Readers;
with Unicode.CES;
with Sancta.Allocation.Problems; use Sancta.Allocation.Problems;
with Sancta.Geometry;

package body Sancta.Allocation.Missions is

   use Ada.Strings.Unbounded;

   type Robot_Info is record
      Id     : Unbounded_String;
      At_Pos : Sancta.Geometry.Point;
      Closed : Boolean := True;
      Mult   : Positive := 1;
      Has_End : Boolean := False;
      End_Pos : Sancta.Geometry.Point;
      --  A depot of its own where the closed tour ends (end_x, end_y).
   end record;

   type Task_Info is record
      Id     : Unbounded_String;
      First  : Positive := 1;      --  index in the points vector
      Count  : Natural := 0;
      Robots : Unbounded_String;   --  "" = all
      Line   : Positive := 1;
   end record;

   type Done_Info is record
      Robot : Unbounded_String;
      Tasks : Unbounded_String;
      Line  : Positive := 1;
   end record;

   package Robot_Vectors is new Ada.Containers.Vectors (Positive, Robot_Info);
   package Task_Vectors is new Ada.Containers.Vectors (Positive, Task_Info);
   package Point_Vectors is new Ada.Containers.Vectors (Positive, Sancta.Geometry.Point,
                                                        Sancta.Geometry."=");
   package Done_Vectors is new Ada.Containers.Vectors (Positive, Done_Info);
   package String_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   type Frame_Kind is (Other, Root, Group, Top_Or, Inner_Or, Inner_And);
   --  Group: an <and> (or <plan>) outside any <or>: its children are all
   --  done, so it only groups. Top_Or: the outermost <or> of a subtree, one
   --  task of the problem. Inner_Or: an <or> nested in it (its alternatives
   --  join the outer ones). Inner_And: an <and> inside an <or>.

   type Frame is record
      Kind   : Frame_Kind := Other;
      Line   : Positive := 1;
      Leaves : Natural := 0;
      --  Inner_And: alternatives (leaves) seen below it so far.
   end record;

   package Frame_Vectors is new Ada.Containers.Vectors (Positive, Frame);

   type Handler is new Sax.Readers.Reader with record
      File   : Unbounded_String;
      Scale  : Long_Float := 100.0;
      Robots : Robot_Vectors.Vector;
      Tasks  : Task_Vectors.Vector;
      Points : Point_Vectors.Vector;
      Done   : Done_Vectors.Vector;
      Stack  : Frame_Vectors.Vector;
      --  One frame per open element (the <mission> root included).
      Root_Seen : Boolean := False;
   end record;

   overriding procedure Start_Element
     (H             : in out Handler;
      Namespace_URI : Unicode.CES.Byte_Sequence := "";
      Local_Name    : Unicode.CES.Byte_Sequence := "";
      Qname         : Unicode.CES.Byte_Sequence := "";
      Atts          : Sax.Attributes.Attributes'Class);

   overriding procedure End_Element
     (H             : in out Handler;
      Namespace_URI : Unicode.CES.Byte_Sequence := "";
      Local_Name    : Unicode.CES.Byte_Sequence := "";
      Qname         : Unicode.CES.Byte_Sequence := "");

   function Line (H : Handler'Class) return Positive is
     (Positive'Max (1, H.Current_Location.Line));

   procedure Fail (H : Handler'Class; Reason : String) with No_Return;
   procedure Fail (H : Handler'Class; Reason : String) is
   begin
      raise Format_Error with To_String (H.File) & ":"
        & Ada.Strings.Fixed.Trim (Line (H)'Image, Ada.Strings.Left) & ": " & Reason;
   end Fail;

   function Attr (H : Handler'Class; Atts : Sax.Attributes.Attributes'Class; Name : String;
                  Element : String; Default : String := "" & ASCII.NUL) return String
   is
      I : constant Integer := Sax.Attributes.Get_Index (Atts, Name);
   begin
      if I < 0 then
         if Default = "" & ASCII.NUL then
            Fail (H, "<" & Element & "> needs attribute '" & Name & "'");
         end if;
         return Default;
      end if;
      return Sax.Attributes.Get_Value (Atts, I);
   end Attr;

   function In_Or (H : Handler'Class) return Boolean is
     (for some F of H.Stack => F.Kind = Top_Or);

   function Line_Image (L : Positive) return String is
     (Ada.Strings.Fixed.Trim (L'Image, Ada.Strings.Left));

   procedure Add_Alternative (H : in out Handler'Class; At_Pos : Sancta.Geometry.Point);
   --  One more alternative for the enclosing top <or>; refused when an
   --  enclosing <and> inside that <or> already has one (a compound
   --  alternative, not modelled yet).

   procedure Add_Alternative (H : in out Handler'Class; At_Pos : Sancta.Geometry.Point) is
   begin
      for I in H.Stack.First_Index .. H.Stack.Last_Index loop
         if H.Stack (I).Kind = Inner_And then
            if H.Stack (I).Leaves > 0 then
               Fail (H, "<and> (line " & Line_Image (H.Stack (I).Line)
                     & ") inside <or id=""" & To_String (H.Tasks.Last_Element.Id)
                     & """> has more than one task: an alternative made of several"
                     & " tasks is not supported yet");
            end if;
            declare
               F : Frame := H.Stack (I);
            begin
               F.Leaves := F.Leaves + 1;
               H.Stack.Replace_Element (I, F);
            end;
         end if;
      end loop;
      H.Points.Append (At_Pos);
      declare
         T : Task_Info := H.Tasks.Last_Element;
      begin
         T.Count := T.Count + 1;
         H.Tasks.Replace_Element (H.Tasks.Last_Index, T);
      end;
   end Add_Alternative;

   function Real_Attr (H : Handler'Class; Atts : Sax.Attributes.Attributes'Class; Name : String;
                       Element : String) return Sancta.Geometry.Real
   is
      S : constant String := Attr (H, Atts, Name, Element);
   begin
      return Sancta.Geometry.Real'Value (S);
   exception
      when Constraint_Error =>
         Fail (H, "<" & Element & "> attribute " & Name & "='" & S & "' is not a number");
   end Real_Attr;

   overriding procedure Start_Element
     (H             : in out Handler;
      Namespace_URI : Unicode.CES.Byte_Sequence := "";
      Local_Name    : Unicode.CES.Byte_Sequence := "";
      Qname         : Unicode.CES.Byte_Sequence := "";
      Atts          : Sax.Attributes.Attributes'Class)
   is
      pragma Unreferenced (Namespace_URI, Qname);
      E : constant String := Local_Name;
      Parent : constant Frame_Kind :=
        (if H.Stack.Is_Empty then Other else H.Stack.Last_Element.Kind);
      Pushed : Frame := (Other, Line (H), 0);
   begin
      if H.Root_Seen and then E in "robot" | "done" and then Parent /= Root then
         Fail (H, "<" & E & "> must be a child of <mission>");
      elsif H.Root_Seen and then E in "task" | "or" | "and" | "plan" | "at"
        and then Parent = Other
      then
         Fail (H, "<" & E & "> must be inside <mission>, <and> or <or>");
      end if;
      if not H.Root_Seen then
         if E /= "mission" then
            Fail (H, "root element is <" & E & ">, expected <mission>");
         end if;
         H.Root_Seen := True;
         Pushed.Kind := Root;
         declare
            S : constant String := Attr (H, Atts, "scale", E, "");
         begin
            if S /= "" and then H.Scale = 0.0 then
               H.Scale := Long_Float'Value (S);
               if H.Scale <= 0.0 or else H.Scale > 1.0E6 then
                  Fail (H, "scale='" & S & "' must be in (0, 1e6]");
               end if;
            end if;
         exception
            when Constraint_Error =>
               Fail (H, "scale='" & S & "' is not a number");
         end;
         if H.Scale = 0.0 then
            H.Scale := 100.0;
         end if;
      elsif E = "robot" then
         declare
            Ret : constant String := Attr (H, Atts, "return", E, "true");
            C   : constant String := Attr (H, Atts, "cost", E, "1");
            R   : Robot_Info;
         begin
            R.Id := To_Unbounded_String (Attr (H, Atts, "id", E));
            R.At_Pos := (Real_Attr (H, Atts, "x", E), Real_Attr (H, Atts, "y", E));
            if Ret not in "true" | "false" then
               Fail (H, "<robot> return='" & Ret & "' is not true or false");
            end if;
            R.Closed := Ret = "true";
            if Sax.Attributes.Get_Index (Atts, "end_x") >= 0
              or else Sax.Attributes.Get_Index (Atts, "end_y") >= 0
            then
               if not R.Closed then
                  Fail (H, "<robot> end_x/end_y with return='false': an open tour has no end");
               end if;
               R.Has_End := True;
               R.End_Pos := (Real_Attr (H, Atts, "end_x", E), Real_Attr (H, Atts, "end_y", E));
            end if;
            begin
               R.Mult := Positive'Value (C);
            exception
               when Constraint_Error =>
                  Fail (H, "<robot> cost='" & C & "' is not a positive integer");
            end;
            for X of H.Robots loop
               if X.Id = R.Id then
                  Fail (H, "robot '" & To_String (R.Id) & "' defined twice");
               end if;
            end loop;
            H.Robots.Append (R);
         end;
      elsif E in "and" | "plan" then
         Pushed.Kind := (if In_Or (H) then Inner_And else Group);
      elsif In_Or (H) and then E = "or" then
         Pushed.Kind := Inner_Or;
      elsif In_Or (H) and then E in "task" | "at" then
         if Sax.Attributes.Get_Index (Atts, "robots") >= 0 then
            Fail (H, "<" & E & "> inside <or>: put 'robots' on the outermost <or>");
         end if;
         Add_Alternative (H, (Real_Attr (H, Atts, "x", E), Real_Attr (H, Atts, "y", E)));
      elsif E = "task" or else E = "or" then
         declare
            T : Task_Info;
         begin
            T.Id := To_Unbounded_String (Attr (H, Atts, "id", E));
            T.Robots := To_Unbounded_String (Attr (H, Atts, "robots", E, ""));
            T.Line := Line (H);
            T.First := Natural (H.Points.Length) + 1;
            for X of H.Tasks loop
               if X.Id = T.Id then
                  Fail (H, "task '" & To_String (T.Id) & "' defined twice");
               end if;
            end loop;
            if E = "task" then
               H.Points.Append (Sancta.Geometry.Point'(Real_Attr (H, Atts, "x", E),
                                                       Real_Attr (H, Atts, "y", E)));
               T.Count := 1;
            else
               Pushed.Kind := Top_Or;
            end if;
            H.Tasks.Append (T);
         end;
      elsif E = "at" then
         Fail (H, "<at> outside <or>");
      elsif E = "done" then
         H.Done.Append (Done_Info'(To_Unbounded_String (Attr (H, Atts, "robot", E)),
                         To_Unbounded_String (Attr (H, Atts, "tasks", E)), Line (H)));
      else
         Fail (H, "unknown element <" & E
               & "> (expected robot, task, or, and, plan, at, done)");
      end if;
      H.Stack.Append (Pushed);
   end Start_Element;

   overriding procedure End_Element
     (H             : in out Handler;
      Namespace_URI : Unicode.CES.Byte_Sequence := "";
      Local_Name    : Unicode.CES.Byte_Sequence := "";
      Qname         : Unicode.CES.Byte_Sequence := "")
   is
      pragma Unreferenced (Namespace_URI, Qname, Local_Name);
      Closing : constant Frame_Kind := H.Stack.Last_Element.Kind;
   begin
      H.Stack.Delete_Last;
      if Closing = Top_Or and then H.Tasks.Last_Element.Count = 0 then
         Fail (H, "<or id=""" & To_String (H.Tasks.Last_Element.Id)
               & """> has no alternative (<at>, <task>)");
      end if;
   end End_Element;

   function Split (S : String) return String_Vectors.Vector is
      Result : String_Vectors.Vector;
      First  : Positive := S'First;
   begin
      for I in S'Range loop
         if S (I) = ',' then
            Result.Append (Ada.Strings.Fixed.Trim (S (First .. I - 1), Ada.Strings.Both));
            First := I + 1;
         end if;
      end loop;
      if S'Length > 0 then
         Result.Append (Ada.Strings.Fixed.Trim (S (First .. S'Last), Ada.Strings.Both));
      end if;
      return Result;
   end Split;

   function Read (File : String; Scale : Long_Float := 0.0) return Problem_Access is
      H     : Handler;
      Input : Input_Sources.File.File_Input;
   begin
      if not Ada.Directories.Exists (File) then
         raise Format_Error with File & ":1: no such file";
      end if;
      H.File := To_Unbounded_String (File);
      H.Scale := Scale;
      Input_Sources.File.Open (File, Input);
      begin
         H.Parse (Input);
      exception
         when E : Sax.Readers.XML_Fatal_Error =>
            Input_Sources.File.Close (Input);
            raise Format_Error with File & ":" & Ada.Exceptions.Exception_Message (E);
         when others =>
            Input_Sources.File.Close (Input);
            raise;
      end;
      Input_Sources.File.Close (Input);
      if H.Robots.Is_Empty then
         raise Format_Error with File & ":1: no <robot>";
      elsif H.Tasks.Is_Empty then
         raise Format_Error with File & ":1: no <task> or <or>";
      end if;
      declare
         NR : constant Positive := Natural (H.Robots.Length);
         NT : constant Positive := Natural (H.Tasks.Length);
         function Ends return Natural;
         function Ends return Natural is
            N : Natural := 0;
         begin
            for X of H.Robots loop
               if X.Has_End then
                  N := N + 1;
               end if;
            end loop;
            return N;
         end Ends;
         NE : constant Natural := Ends;
         NL : constant Positive := NR + Natural (H.Points.Length) + NE;
         P  : constant Problem_Access := Create (NL, NT, NR, Natural (H.Points.Length));
         Pts : Point_Array (1 .. NL);

         function Robot_Index (Id : String; Where : Positive) return Positive is
         begin
            for R in 1 .. NR loop
               if To_String (H.Robots (R).Id) = Id then
                  return R;
               end if;
            end loop;
            raise Format_Error with File & ":" & Ada.Strings.Fixed.Trim (Where'Image,
              Ada.Strings.Left) & ": unknown robot '" & Id & "'";
         end Robot_Index;

         function Task_Index (Id : String; Where : Positive) return Positive is
         begin
            for T in 1 .. NT loop
               if To_String (H.Tasks (T).Id) = Id then
                  return T;
               end if;
            end loop;
            raise Format_Error with File & ":" & Ada.Strings.Fixed.Trim (Where'Image,
              Ada.Strings.Left) & ": unknown task '" & Id & "'";
         end Task_Index;
      begin
         for R in 1 .. NR loop
            Pts (R) := H.Robots (R).At_Pos;
         end loop;
         for K in 1 .. Natural (H.Points.Length) loop
            Pts (NR + K) := H.Points (K);
         end loop;
         declare
            Next : Positive := NR + Natural (H.Points.Length) + 1;
         begin
            for R in 1 .. NR loop
               if H.Robots (R).Has_End then
                  Pts (Next) := H.Robots (R).End_Pos;
                  Next := Next + 1;
               end if;
            end loop;
         end;
         Set_Euclidean (P.all, Pts, H.Scale, Round => True);
         declare
            Next : Positive := NR + Natural (H.Points.Length) + 1;
         begin
            for R in 1 .. NR loop
               Set_Robot (P.all, R, R, H.Robots (R).Closed, H.Robots (R).Mult);
               if H.Robots (R).Has_End then
                  Set_Robot_End (P.all, R, Next);
                  Next := Next + 1;
               end if;
            end loop;
         end;
         for T in 1 .. NT loop
            declare
               Info : constant Task_Info := H.Tasks (T);
               Locs : Location_Array (1 .. Info.Count);
            begin
               for K in Locs'Range loop
                  Locs (K) := NR + Info.First + K - 1;
               end loop;
               Set_Task_Alternatives (P.all, T, Locs);
               if Info.Robots /= "" then
                  declare
                     Allowed : array (1 .. NR) of Boolean := [others => False];
                  begin
                     for Id of Split (To_String (Info.Robots)) loop
                        Allowed (Robot_Index (Id, Info.Line)) := True;
                     end loop;
                     for R in 1 .. NR loop
                        if not Allowed (R) then
                           Forbid (P.all, R, T);
                        end if;
                     end loop;
                  end;
               end if;
            end;
         end loop;
         for D of H.Done loop
            declare
               R : constant Positive := Robot_Index (To_String (D.Robot), D.Line);
               Ids : constant String_Vectors.Vector := Split (To_String (D.Tasks));
               Ts : Location_Array (1 .. Natural (Ids.Length));
            begin
               for K in Ts'Range loop
                  Ts (K) := Task_Index (Ids (K), D.Line);
                  if P.Is_Frozen (Ts (K)) then
                     raise Format_Error with File & ":" & Ada.Strings.Fixed.Trim
                       (D.Line'Image, Ada.Strings.Left) & ": task '" & Ids (K)
                       & "' is done twice";
                  end if;
               end loop;
               Freeze (P.all, R, Ts);
            end;
         end loop;
         P.Min_Tasks := 0;
         declare
            Why : constant String := Check (P.all);
         begin
            if Why /= "" then
               raise Format_Error with File & ":1: " & Why;
            end if;
         end;
         return P;
      end;
   end Read;

end Sancta.Allocation.Missions;
