with Ada.Directories;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Sancta.Runtime.XML_Trees;
with Sancta.Runtime.Values;

package body Sancta.Team.Missions is

   use Sancta.Geometry;
   package XT renames Sancta.Runtime.XML_Trees;
   subtype Element_Id is XT.Element_Id;
   subtype Position is XT.Position;
   function Image (Where : Position) return String renames XT.Image;

   function Entry_Point (T : Mission_Task; Choice : Positive) return Point is
     (case T.Kind is
         when Goto_Pose       => T.Points (1),
         when Explore_Segment => T.Points (Choice),
         when Choose_Entry    => T.Points (Choice));

   function Exit_Point (T : Mission_Task; Choice : Positive) return Point is
     (case T.Kind is
         when Goto_Pose       => T.Points (1),
         when Explore_Segment => T.Points (3 - Choice),
         when Choose_Entry    => T.Points (Choice));

   function Inner_Length (T : Mission_Task; Choice : Positive) return Long_Float is
     (Long_Float (Distance (Entry_Point (T, Choice), Exit_Point (T, Choice))));

   function Read (File : String) return Mission is
      Tree   : XT.Tree;
      Result : Mission;

      procedure Raise_At (Where : Position; Text : String)
        with No_Return;

      procedure Raise_At (Where : Position; Text : String) is
      begin
         raise Format_Error with Image (Where) & ": " & Text;
      end Raise_At;

      function Real_Of (E : Element_Id; Name : String; Default : Real := Real'First)
        return Real
      is
      begin
         if not Tree.Has_Attribute (E, Name) then
            if Default /= Real'First then
               return Default;
            end if;
            Raise_At (Tree.Where (E), "<" & Tree.Name (E) & "> needs attribute " & Name);
         end if;
         declare
            Text  : constant String := Tree.Attribute_Value (E, Name);
            Value : Long_Float;
         begin
            begin
               Value := Long_Float'Value (Text);
            exception
               when Constraint_Error =>
                  Raise_At (Tree.Attribute_Where (E, Name),
                            Name & "=""" & Text & """ is not a number");
            end;
            if not Value'Valid or else abs Value > Max_Coordinate then
               Raise_At (Tree.Attribute_Where (E, Name),
                         Name & "=""" & Text & """ is not a finite number within +/-1e6");
            end if;
            return Real (Value);
         end;
      end Real_Of;

      function Id_Of (E : Element_Id) return Unbounded_String is
      begin
         if not Tree.Has_Attribute (E, "id") then
            Raise_At (Tree.Where (E), "<" & Tree.Name (E) & "> needs attribute id");
         end if;
         declare
            Id : constant String := Tree.Attribute_Value (E, "id");
         begin
            if Id = ""
              or else (for some C of Id => not (C in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_'))
            then
               Raise_At (Tree.Attribute_Where (E, "id"),
                         "id """ & Id & """: only letters, digits and '_' are allowed");
            end if;
            return To_Unbounded_String (Id);
         end;
      end Id_Of;

      function Known (Id : Unbounded_String) return Boolean is
        ((for some T of Result.Tasks => T.Id = Id)
         or else (for some R of Result.Robots => R.Id = Id));

      Root : Element_Id;
   begin
      begin
         XT.Load (File, Tree);
      exception
         when E : others =>
            raise Format_Error with Ada.Exceptions.Exception_Message (E);
      end;
      Root := Tree.Root;
      if Tree.Name (Root) /= "mission" then
         Raise_At (Tree.Where (Root), "expected <mission>, found <" & Tree.Name (Root) & ">");
      end if;
      if Tree.Has_Attribute (Root, "name") then
         Result.Name := To_Unbounded_String (Tree.Attribute_Value (Root, "name"));
      end if;
      if Tree.Has_Attribute (Root, "world") then
         declare
            W : constant String := Tree.Attribute_Value (Root, "world");
         begin
            Result.World := To_Unbounded_String
              (if W /= "" and then W (W'First) = '/' then W
               else Ada.Directories.Containing_Directory (File) & "/" & W);
         end;
      end if;
      for E of Tree.Children (Root) loop

         declare
            Name : constant String := Tree.Name (E);
            T    : Mission_Task;
         begin
            if Natural (Result.Tasks.Length) + Natural (Result.Robots.Length) >= Max_Entries then
               Raise_At (Tree.Where (E), "more than" & Natural'Image (Max_Entries)
                         & " robots and tasks: too many for a team mission");
            end if;
            if Name = "robot" then
               declare
                  R : constant Robot_Start :=
                    (Id_Of (E), (Real_Of (E, "x"), Real_Of (E, "y"), Real_Of (E, "yaw", 0.0)));
               begin
                  if Known (R.Id) then
                     Raise_At (Tree.Where (E), "duplicate id " & To_String (R.Id));
                  end if;
                  Result.Robots.Append (R);
               end;
            elsif Name in "goto" | "explore" | "choose" then
               T.Id := Id_Of (E);
               if Known (T.Id) then
                  Raise_At (Tree.Where (E), "duplicate id " & To_String (T.Id));
               end if;
               if Name = "goto" then
                  T.Kind := Goto_Pose;
                  T.Points.Append (Point'(Real_Of (E, "x"), Real_Of (E, "y")));
               elsif Name = "explore" then
                  T.Kind := Explore_Segment;
                  T.Points.Append (Point'(Real_Of (E, "x1"), Real_Of (E, "y1")));
                  T.Points.Append (Point'(Real_Of (E, "x2"), Real_Of (E, "y2")));
               else
                  T.Kind := Choose_Entry;
                  for A of Tree.Children (E) loop
                     if Tree.Name (A) /= "at" then
                        Raise_At (Tree.Where (A), "expected <at> in <choose>, found <"
                                  & Tree.Name (A) & ">");
                     end if;
                     T.Points.Append (Point'(Real_Of (A, "x"), Real_Of (A, "y")));
                  end loop;
                  if T.Points.Is_Empty then
                     Raise_At (Tree.Where (E), "<choose> needs at least one <at>");
                  end if;
               end if;
               Result.Tasks.Append (T);
            else
               Raise_At (Tree.Where (E), "unknown element <" & Name
                         & "> (expected robot, goto, explore or choose)");
            end if;
         end;
      end loop;
      if Result.Tasks.Is_Empty then
         Raise_At (Tree.Where (Root), "the mission has no task");
      end if;
      return Result;
   end Read;

   function Encode (T : Mission_Task) return String is
      Result : Unbounded_String :=
        To_Unbounded_String
          (case T.Kind is
              when Goto_Pose => "goto",
              when Explore_Segment => "explore",
              when Choose_Entry => "choose");
   begin
      for P of T.Points loop
         Append (Result, ";" & Runtime.Values.Real_Image (Long_Float (P.X)) & ","
                 & Runtime.Values.Real_Image (Long_Float (P.Y)));
      end loop;
      return To_String (Result);
   end Encode;

   function Decode (Id, Text : String) return Mission_Task is
      Result : Mission_Task := (Id => To_Unbounded_String (Id), others => <>);
      First  : Positive := Text'First;
      Part   : Natural := 0;
   begin
      loop
         declare
            Semi  : constant Natural := Ada.Strings.Fixed.Index (Text (First .. Text'Last), ";");
            Last  : constant Natural := (if Semi = 0 then Text'Last else Semi - 1);
            Field : constant String := Text (First .. Last);
         begin
            Part := Part + 1;
            if Part = 1 then
               if Field = "goto" then
                  Result.Kind := Goto_Pose;
               elsif Field = "explore" then
                  Result.Kind := Explore_Segment;
               elsif Field = "choose" then
                  Result.Kind := Choose_Entry;
               else
                  raise Format_Error with "task " & Id & ": unknown kind """ & Field & """";
               end if;
            else
               declare
                  Comma : constant Natural := Ada.Strings.Fixed.Index (Field, ",");
               begin
                  if Comma = 0 then
                     raise Format_Error with "task " & Id & ": point """ & Field
                       & """ is not x,y";
                  end if;
                  Result.Points.Append
                    (Point'(Real'Value (Field (Field'First .. Comma - 1)),
                      Real'Value (Field (Comma + 1 .. Field'Last))));
               end;
            end if;
            exit when Semi = 0;
            First := Semi + 1;
         end;
      end loop;
      if Result.Points.Is_Empty
        or else (Result.Kind = Explore_Segment and then Natural (Result.Points.Length) /= 2)
        or else (Result.Kind = Goto_Pose and then Natural (Result.Points.Length) /= 1)
      then
         raise Format_Error with "task " & Id & ": wrong number of points in """ & Text & """";
      end if;
      return Result;
   exception
      when Constraint_Error =>
         raise Format_Error with "task " & Id & ": malformed """ & Text & """";
   end Decode;

end Sancta.Team.Missions;
