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

package body Sancta.Allocation.Problem_Files is

   use Ada.Strings.Unbounded;

   type Robot_Info is record
      Id     : Unbounded_String;
      At_Pos : Sancta.Geometry.Point;
      Closed : Boolean := True;
      Mult   : Positive := 1;
      Has_End : Boolean := False;
      End_Pos : Sancta.Geometry.Point;
      --  A depot of its own where the closed tour ends (end_x, end_y).
      Factor : Long_Float := 1.0;
      Manhattan : Boolean := False;
      --  Its own cost function: factor x (Euclidean or Manhattan) distance.
      Line   : Positive := 1;
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

   --  The plan as written: elements <task>/<at> (leaves), <and>/<plan>,
   --  <or>, linked as a tree (Parent 0: a child of <mission>).
   type Element_Kind is (Leaf, And_Element, Or_Element);
   type Element is record
      Kind     : Element_Kind := Leaf;
      Id       : Unbounded_String;
      Robots   : Unbounded_String;
      Pos      : Sancta.Geometry.Point := (0.0, 0.0);
      Line     : Positive := 1;
      Parent   : Natural := 0;
      First_Child, Last_Child, Next : Natural := 0;
      Children : Natural := 0;
      Leaves   : Natural := 0;    --  leaves below it
   end record;

   --  What to do to the problem's plan once it exists: a new AND / OR node
   --  under the node made by operation Parent (0: root), or a task there.
   type Plan_Op is record
      Kind    : Node_Kind := Task_Node;
      Parent  : Natural := 0;
      Task_Id : Natural := 0;
      Name    : Unbounded_String;
      Line    : Positive := 1;
   end record;

   package Robot_Vectors is new Ada.Containers.Vectors (Positive, Robot_Info);
   package Task_Vectors is new Ada.Containers.Vectors (Positive, Task_Info);
   package Point_Vectors is new Ada.Containers.Vectors (Positive, Sancta.Geometry.Point,
                                                        Sancta.Geometry."=");
   package Done_Vectors is new Ada.Containers.Vectors (Positive, Done_Info);
   package String_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);
   package Element_Vectors is new Ada.Containers.Vectors (Positive, Element);
   package Op_Vectors is new Ada.Containers.Vectors (Positive, Plan_Op);

   type Frame_Kind is (Other, Root, Plan_Element);
   --  Plan_Element: a <task>, <at>, <and>, <plan> or <or> (its Element).

   type Frame is record
      Kind    : Frame_Kind := Other;
      Element : Natural := 0;
   end record;

   package Frame_Vectors is new Ada.Containers.Vectors (Positive, Frame);

   type Handler is new Sax.Readers.Reader with record
      File   : Unbounded_String;
      Scale  : Long_Float := 100.0;
      Robots : Robot_Vectors.Vector;
      Tasks  : Task_Vectors.Vector;
      Points : Point_Vectors.Vector;
      Done   : Done_Vectors.Vector;
      Elements : Element_Vectors.Vector;
      Ops    : Op_Vectors.Vector;
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

   overriding procedure Start_DTD
     (H         : in out Handler;
      Name      : Unicode.CES.Byte_Sequence;
      Public_Id : Unicode.CES.Byte_Sequence := "";
      System_Id : Unicode.CES.Byte_Sequence := "");

   Max_Elements : constant := 10_000;
   --  Robots, tasks and plan elements of one mission: beyond, an error
   --  (the planners' work grows with the square of the task count).

   Max_Coordinate : constant := 1.0E7;
   --  Metres (or the file's unit) from the origin.

   function Line (H : Handler'Class) return Positive is
     (Positive'Max (1, H.Current_Location.Line));

   function Line_Image (L : Positive) return String is
     (Ada.Strings.Fixed.Trim (L'Image, Ada.Strings.Left));

   procedure Fail (File : String; Where : Positive; Reason : String) with No_Return;
   procedure Fail (File : String; Where : Positive; Reason : String) is
   begin
      raise Format_Error with File & ":" & Line_Image (Where) & ": " & Reason;
   end Fail;

   procedure Fail (H : Handler'Class; Reason : String) with No_Return;
   procedure Fail (H : Handler'Class; Reason : String) is
   begin
      Fail (To_String (H.File), Line (H), Reason);
   end Fail;

   overriding procedure Start_DTD
     (H         : in out Handler;
      Name      : Unicode.CES.Byte_Sequence;
      Public_Id : Unicode.CES.Byte_Sequence := "";
      System_Id : Unicode.CES.Byte_Sequence := "")
   is
      pragma Unreferenced (Name, Public_Id, System_Id);
   begin
      Fail (H, "a DOCTYPE declaration is not allowed (no DTD, no entities)");
   end Start_DTD;

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
      declare
         Value : constant String := Sax.Attributes.Get_Value (Atts, I);
      begin
         if (for some C of Value => C < ' ') then
            Fail (H, "<" & Element & "> attribute " & Name & " has a control character");
         end if;
         return Value;
      end;
   end Attr;

   --  The innermost open <or> element (0: none).
   function Enclosing_Or (H : Handler'Class) return Natural is
   begin
      for I in reverse H.Stack.First_Index .. H.Stack.Last_Index loop
         if H.Stack (I).Kind = Plan_Element
           and then H.Elements (H.Stack (I).Element).Kind = Or_Element
         then
            return H.Stack (I).Element;
         end if;
      end loop;
      return 0;
   end Enclosing_Or;

   function In_Or (H : Handler'Class) return Boolean is (Enclosing_Or (H) /= 0);

   --  The id of the outermost <or> around element E (for messages).
   function Or_Label (H : Handler'Class; E : Natural) return String is
      X : Natural := E;
      Label : Unbounded_String;
   begin
      while X /= 0 loop
         if H.Elements (X).Kind = Or_Element and then H.Elements (X).Id /= "" then
            Label := H.Elements (X).Id;
         end if;
         X := H.Elements (X).Parent;
      end loop;
      return To_String (Label);
   end Or_Label;

   function Real_Attr (H : Handler'Class; Atts : Sax.Attributes.Attributes'Class; Name : String;
                       Element : String) return Sancta.Geometry.Real
   is
      S : constant String := Attr (H, Atts, Name, Element);
      X : Long_Float;
   begin
      begin
         X := Long_Float'Value (S);
      exception
         when Constraint_Error =>
            Fail (H, "<" & Element & "> attribute " & Name & "='" & S & "' is not a number");
      end;
      if not X'Valid or else abs X > Max_Coordinate then
         Fail (H, "<" & Element & "> attribute " & Name & "='" & S
               & "' is not a finite number within +/-1e7");
      end if;
      return Sancta.Geometry.Real (X);
   end Real_Attr;

   --  A new plan element under the innermost open one.
   procedure Add_Element (H : in out Handler'Class; E : in out Element; Index : out Positive) is
      Parent : Natural := 0;
   begin
      if not H.Stack.Is_Empty and then H.Stack.Last_Element.Kind = Plan_Element then
         Parent := H.Stack.Last_Element.Element;
      end if;
      Index := Natural (H.Elements.Length) + 1;
      E.Parent := Parent;
      if Parent /= 0 then
         declare
            Up : Element := H.Elements (Parent);
         begin
            if Up.Last_Child = 0 then
               Up.First_Child := Index;
            else
               declare
                  Prev : Element := H.Elements (Up.Last_Child);
               begin
                  Prev.Next := Index;
                  H.Elements.Replace_Element (Up.Last_Child, Prev);
               end;
            end if;
            Up.Last_Child := Index;
            Up.Children := Up.Children + 1;
            H.Elements.Replace_Element (Parent, Up);
         end;
      end if;
      if E.Kind = Leaf then
         E.Leaves := 1;
         declare
            X : Natural := Parent;
         begin
            while X /= 0 loop
               declare
                  Up : Element := H.Elements (X);
               begin
                  Up.Leaves := Up.Leaves + 1;
                  H.Elements.Replace_Element (X, Up);
                  X := Up.Parent;
               end;
            end loop;
         end;
      end if;
      H.Elements.Append (E);
   end Add_Element;

   overriding procedure Start_Element
     (H             : in out Handler;
      Namespace_URI : Unicode.CES.Byte_Sequence := "";
      Local_Name    : Unicode.CES.Byte_Sequence := "";
      Qname         : Unicode.CES.Byte_Sequence := "";
      Atts          : Sax.Attributes.Attributes'Class)
   is
      pragma Unreferenced (Namespace_URI, Qname);
      E : constant String := Local_Name;
      Parent : constant Frame :=
        (if H.Stack.Is_Empty then (Other, 0) else H.Stack.Last_Element);
      Parent_Leaf : constant Boolean :=
        Parent.Kind = Plan_Element and then H.Elements (Parent.Element).Kind = Leaf;
      Pushed : Frame := (Other, 0);
   begin
      if Natural (H.Elements.Length) + Natural (H.Robots.Length) >= Max_Elements then
         Fail (H, "more than" & Natural'Image (Max_Elements)
               & " tasks and robots: too many tasks for sancta plan");
      end if;
      if H.Root_Seen and then E in "robot" | "done" and then Parent.Kind /= Root then
         Fail (H, "<" & E & "> must be a child of <mission>");
      elsif H.Root_Seen and then E in "task" | "or" | "and" | "plan" | "at"
        and then (Parent.Kind = Other or else Parent_Leaf)
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
            F   : constant String := Attr (H, Atts, "factor", E, "1");
            M   : constant String := Attr (H, Atts, "metric", E, "euclidean");
            R   : Robot_Info;
         begin
            R.Id := To_Unbounded_String (Attr (H, Atts, "id", E));
            R.Line := Line (H);
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
            begin
               R.Factor := Long_Float'Value (F);
               if R.Factor <= 0.0 or else R.Factor > 1.0E6 then
                  raise Constraint_Error;
               end if;
            exception
               when Constraint_Error =>
                  Fail (H, "<robot> factor='" & F & "' is not a number in (0, 1e6]");
            end;
            if M not in "euclidean" | "manhattan" then
               Fail (H, "<robot> metric='" & M & "' is not euclidean or manhattan");
            end if;
            R.Manhattan := M = "manhattan";
            for X of H.Robots loop
               if X.Id = R.Id then
                  Fail (H, "robot '" & To_String (R.Id) & "' defined twice");
               end if;
            end loop;
            H.Robots.Append (R);
         end;
      elsif E in "and" | "plan" | "or" | "task" | "at" then
         declare
            El : Element;
            Index : Positive;
         begin
            El.Line := Line (H);
            if E = "at" and then not In_Or (H) then
               Fail (H, "<at> outside <or>");
            end if;
            if E in "task" | "at" and then In_Or (H)
              and then Sax.Attributes.Get_Index (Atts, "robots") >= 0
            then
               Fail (H, "<" & E & "> inside <or>: put 'robots' on the outermost <or>");
            end if;
            if E in "task" | "or" then
               --  An id is needed outside <or> (inside, a default is made).
               El.Id := To_Unbounded_String
                 (Attr (H, Atts, "id", E, (if In_Or (H) then "" else "" & ASCII.NUL)));
               El.Robots := To_Unbounded_String (Attr (H, Atts, "robots", E, ""));
            end if;
            if E in "task" | "at" then
               El.Kind := Leaf;
               El.Pos := (Real_Attr (H, Atts, "x", E), Real_Attr (H, Atts, "y", E));
            elsif E = "or" then
               El.Kind := Or_Element;
            else
               El.Kind := And_Element;
            end if;
            Add_Element (H, El, Index);
            Pushed := (Plan_Element, Index);
         end;
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
      Closing : constant Frame := H.Stack.Last_Element;
   begin
      H.Stack.Delete_Last;
      if Closing.Kind = Plan_Element then
         declare
            El : constant Element := H.Elements (Closing.Element);
            C  : Natural := El.First_Child;
            K  : Natural := 0;
         begin
            if El.Kind = Or_Element and then El.Leaves = 0 then
               Fail (H, "<or id=""" & Or_Label (H, Closing.Element)
                     & """> has no alternative (<at>, <task>) in the <or> of line "
                     & Line_Image (El.Line));
            elsif El.Kind = Or_Element then
               while C /= 0 loop
                  K := K + 1;
                  if H.Elements (C).Leaves = 0 then
                     Fail (H, "alternative" & K'Image & " (line "
                           & Line_Image (H.Elements (C).Line) & ") of <or id="""
                           & Or_Label (H, Closing.Element) & """> has no task");
                  end if;
                  C := H.Elements (C).Next;
               end loop;
            end if;
         end;
      end if;
   end End_Element;

   --  An element that stands for one task at one of several locations: a
   --  leaf, an <or> of such elements, or an <and> of exactly one.
   function Is_Flat (H : Handler'Class; E : Positive) return Boolean is
      El : constant Element := H.Elements (E);
      C  : Natural := El.First_Child;
   begin
      case El.Kind is
         when Leaf =>
            return True;
         when And_Element =>
            return El.Children = 1 and then Is_Flat (H, El.First_Child);
         when Or_Element =>
            while C /= 0 loop
               if not Is_Flat (H, C) then
                  return False;
               end if;
               C := H.Elements (C).Next;
            end loop;
            return El.Children > 0;
      end case;
   end Is_Flat;

   procedure Add_Points (H : in out Handler'Class; E : Positive; T : in out Task_Info) is
      El : constant Element := H.Elements (E);
      C  : Natural := El.First_Child;
   begin
      if El.Kind = Leaf then
         H.Points.Append (El.Pos);
         T.Count := T.Count + 1;
      end if;
      while C /= 0 loop
         Add_Points (H, C, T);
         C := H.Elements (C).Next;
      end loop;
   end Add_Points;

   --  Turns element E into tasks and plan operations under the plan node
   --  made by operation Parent_Op (0: none, outside any <or>); Name is the
   --  task id to use when E has none, Robots the inherited restriction.
   procedure Convert
     (H : in out Handler'Class; E : Positive; Parent_Op : Natural; In_Tree : Boolean;
      Name : String; Robots : Unbounded_String)
   is
      El : constant Element := H.Elements (E);
      Id : constant String := (if El.Id /= "" then To_String (El.Id) else Name);
      Rb : constant Unbounded_String := (if El.Robots /= "" then El.Robots else Robots);
      C  : Natural := El.First_Child;
      K  : Natural := 0;
   begin
      if Is_Flat (H, E) and then (El.Kind /= And_Element or else In_Tree) then
         declare
            T : Task_Info;
         begin
            T.Id := To_Unbounded_String (Id);
            T.Robots := Rb;
            T.Line := El.Line;
            T.First := Natural (H.Points.Length) + 1;
            Add_Points (H, E, T);
            H.Tasks.Append (T);
            if In_Tree then
               H.Ops.Append (Plan_Op'(Task_Node, Parent_Op, Natural (H.Tasks.Length),
                                      Null_Unbounded_String, El.Line));
            end if;
         end;
      elsif El.Kind = And_Element and then not In_Tree then
         --  A group outside any <or>: its children are all done.
         while C /= 0 loop
            K := K + 1;
            Convert (H, C, 0, False, Id & "." & Line_Image (K), Rb);
            C := H.Elements (C).Next;
         end loop;
      else
         H.Ops.Append (Plan_Op'((if El.Kind = Or_Element then Or_Node else And_Node),
                                Parent_Op, 0, To_Unbounded_String (Id), El.Line));
         declare
            Me : constant Positive := Natural (H.Ops.Length);
         begin
            while C /= 0 loop
               K := K + 1;
               Convert (H, C, Me, True, Id & "." & Line_Image (K), Rb);
               C := H.Elements (C).Next;
            end loop;
         end;
      end if;
   end Convert;

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
            --  XML/Ada's message starts with "FILE:LINE:COLUMN: " already.
            declare
               Message : constant String := Ada.Exceptions.Exception_Message (E);
            begin
               raise Format_Error with
                 (if Ada.Strings.Fixed.Head (Message, File'Length + 1) = File & ":" then Message
                  else File & ": " & Message);
            end;
         when others =>
            Input_Sources.File.Close (Input);
            raise;
      end;
      Input_Sources.File.Close (Input);
      for E in 1 .. Natural (H.Elements.Length) loop
         if H.Elements (E).Parent = 0 then
            Convert (H, E, 0, False, "", Null_Unbounded_String);
         end if;
      end loop;
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
         for R in 1 .. NR loop
            declare
               Info : constant Robot_Info := H.Robots (R);
            begin
               if Info.Factor /= 1.0 or else Info.Manhattan then
                  for A in 1 .. NL loop
                     for B in 1 .. NL loop
                        declare
                           use Sancta.Geometry;
                           Base : constant Long_Float :=
                             (if Info.Manhattan
                              then Long_Float (abs (Pts (A).X - Pts (B).X)
                                               + abs (Pts (A).Y - Pts (B).Y))
                              else Long_Float (Distance (Pts (A), Pts (B))));
                        begin
                           Set_Robot_Distance
                             (P.all, R, A, B, Cost'Min (Infinity, Cost (Long_Float'Floor
                                (Info.Factor * H.Scale * Base + 0.5))));
                        end;
                     end loop;
                  end loop;
               end if;
            end;
         end loop;
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
         for T in 1 .. NT loop
            P.Task_Names.Append (To_String (H.Tasks (T).Id));
            for U in 1 .. T - 1 loop
               if H.Tasks (U).Id = H.Tasks (T).Id then
                  Fail (File, H.Tasks (T).Line, "task '" & To_String (H.Tasks (T).Id)
                        & "' defined twice (also line " & Line_Image (H.Tasks (U).Line) & ")");
               end if;
            end loop;
         end loop;
         declare
            Node_Of : array (1 .. Natural (H.Ops.Length)) of Natural := [others => 0];
            Ors     : Natural := 0;
         begin
            for K in Node_Of'Range loop
               declare
                  Op : constant Plan_Op := H.Ops (K);
                  Up : constant Natural := (if Op.Parent = 0 then 0 else Node_Of (Op.Parent));
               begin
                  if Op.Kind = Task_Node then
                     Add_Plan_Task (P.all, Up, Op.Task_Id);
                  else
                     if Op.Kind = Or_Node then
                        Ors := Ors + 1;
                        if Ors > NT then
                           Fail (File, Op.Line, "more <or> nodes than tasks (nested <or> with"
                                 & " a single alternative?)");
                        end if;
                        P.Or_Names.Append (To_String (Op.Name));
                     end if;
                     Add_Node (P.all, Op.Kind, Up, Node_Of (K));
                  end if;
               end;
            end loop;
         end;
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
               declare
                  Why : constant String := Check (P.all);
               begin
                  if Why'Length > 12 and then Why (Why'First .. Why'First + 11) = "frozen task "
                  then
                     Fail (File, D.Line, Why);
                  end if;
               end;
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

end Sancta.Allocation.Problem_Files;
