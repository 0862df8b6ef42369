with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Strings.Fixed;

package body Sancta.Views.Scenes is

   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;
   use type Ada.Containers.Count_Type;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);
   use Math;

   Start : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;

   function Elapsed return Duration is
     (Ada.Real_Time.To_Duration (Ada.Real_Time.Clock - Start));

   function Parse_State (Text : String) return Task_State is
     (if Text = "assigned" then Assigned
      elsif Text = "active" then Active
      elsif Text = "done" then Done
      elsif Text = "reallocated" then Reallocated
      else Pending);

   function Tasks_In (S : Scene; State : Task_State) return Natural is
      N : Natural := 0;
   begin
      for T of S.Tasks loop
         if T.State = State then
            N := N + 1;
         end if;
      end loop;
      return N;
   end Tasks_In;

   function Tasks_Done (S : Scene) return Natural is (Tasks_In (S, Done));

   function Find_Task (S : Scene; Id : String) return Natural is
   begin
      for K in 1 .. Natural (S.Tasks.Length) loop
         if S.Tasks (K).Id = Id then
            return K;
         end if;
      end loop;
      return 0;
   end Find_Task;

   function Colour_Index (Robot : String) return Natural is
      First : Natural := Robot'Last + 1;
      Hash  : Natural := 0;
   begin
      while First > Robot'First and then Robot (First - 1) in '0' .. '9' loop
         First := First - 1;
      end loop;
      if First <= Robot'Last and then Robot'Last - First < 6 then
         return Natural'Value (Robot (First .. Robot'Last));
      end if;
      for C of Robot loop
         Hash := (Hash * 31 + Character'Pos (C)) mod 1_000_003;
      end loop;
      return Hash;
   end Colour_Index;

   function Cut (Text : Unbounded_String) return Unbounded_String is
     (if Length (Text) > Max_Text then Unbounded_Slice (Text, 1, Max_Text) else Text);

   Huge : constant Real := 1.0E6;
   --  Coordinates beyond this (m) are malformed.

   function Sane (X : Real) return Boolean is (X = X and then abs X <= Huge);
   --  False for NaN (X /= X), infinities and absurd values.

   function Sane (P : Point) return Boolean is (Sane (P.X) and then Sane (P.Y));

   function Image (X : Real) return String is
      Tenths : constant Long_Long_Integer := Long_Long_Integer (X * 10.0);
      Units  : constant String := Long_Long_Integer'Image (abs Tenths / 10);
   begin
      return (if Tenths < 0 then "-" else "") & Units (Units'First + 1 .. Units'Last) & "."
        & Ada.Strings.Fixed.Trim (Long_Long_Integer'Image (abs Tenths mod 10),
                                  Ada.Strings.Left);
   end Image;

   protected body Store is

      function Left_Out (Id : String) return Boolean is
        (Current.Round > 0 and then In_Round.Contains (Id)
         and then not Current.Round_Robots.Contains (Id));
      --  Once in a round of the team, now left out of its current one.

      procedure Add_Event (Text : String) is
      begin
         Current.Events.Append (Event'(Elapsed, To_Unbounded_String (Text)));
         if Current.Events.Length > Max_Events then
            Current.Events.Delete_First;
         end if;
      end Add_Event;

      procedure Set_Lost_After (Seconds : Duration) is
      begin
         Lost_After := Seconds;
      end Set_Lost_After;

      procedure Note (Text : String) is
      begin
         Add_Event (Text);
      end Note;

      procedure Reject (What : String) is
      begin
         Current.Rejected := Current.Rejected + 1;
         if not Noted.Contains (What) then
            Noted.Append (What);
            Add_Event ("ignored: " & What);
         end if;
      end Reject;

      procedure Update_Robot (Sample : Robot_Sample) is
         Id : constant String := To_String (Cut (Sample.Robot));
      begin
         if Id = "" then
            Reject ("a RobotState without a robot name");
            return;
         elsif not (Sane (Sample.Where.X) and then Sane (Sample.Where.Y)
                    and then Sane (Sample.Where.Yaw))
         then
            Reject ("a RobotState of " & Id & " with a pose out of range");
            return;
         elsif not Current.Robots.Contains (Id) and then Current.Robots.Length >= Max_Robots then
            Reject ("robots beyond" & Max_Robots'Image);
            return;
         end if;
         if not Current.Robots.Contains (Id) then
            Current.Robots.Insert
              (Id, (Id => To_Unbounded_String (Id), Colour => Colour_Index (Id), others => <>));
            Add_Event (Id & " joined");
         end if;
         declare
            R : Robot_View renames Current.Robots.Reference (Id);
            P : constant Point := (Sample.Where.X, Sample.Where.Y);
         begin
            if R.Lost and then not R.Killed and then not Left_Out (Id) then
               Add_Event (Id & " back");
               R.Lost := False;
            end if;
            R.Where := Sample.Where;
            if R.Trail.Is_Empty or else Distance (R.Trail.Last_Element, P) > 0.05 then
               R.Trail.Append (P);
               if R.Trail.Length > Max_Trail then
                  R.Trail.Delete_First (Max_Trail / 4);
               end if;
            end if;
            R.Status := Cut (Sample.Status);
            R.Current_Task := Cut (Sample.Current_Task);
            R.Done := Natural (Sample.Done.Length);
            R.Left := Natural (Sample.Tour.Length);
            R.Tour := Sample.Tour;
            R.Choices :=
              (if Sample.Choices.Length = Sample.Tour.Length then Sample.Choices
               else Choice_Vectors.Empty_Vector);
            R.Planned_Cost := (if Sane (Sample.Planned_Cost) then Sample.Planned_Cost else 0.0);
            R.Distance := (if Sane (Sample.Distance) then Sample.Distance else 0.0);
            R.Plan_Round := Sample.Plan_Round;
            R.Last_Heard := Ada.Real_Time.Clock;
         end;
         Current.Samples := Current.Samples + 1;
      end Update_Robot;

      procedure Update_Plan (Sample : Plan_Sample) is
         Old_Round : constant Natural := Current.Round;
         Old_Plan  : constant Natural := Current.Plan_Round;
      begin
         if Sample.Round < Current.Round
           or else (Sample.Round = Current.Round and then Sample.Plan_Round < Current.Plan_Round)
         then
            return;
            --  A replica behind the latest one seen.
         elsif Sample.Tasks.Length > Max_Tasks then
            Reject ("a TeamPlan of more than" & Max_Tasks'Image & " tasks");
            return;
         end if;
         Current.Team := Cut (Sample.Team);
         Current.Round := Sample.Round;
         Current.Plan_Round := Sample.Plan_Round;
         Current.Proposer := Cut (Sample.Proposer);
         Current.Makespan := (if Sane (Sample.Makespan) then Sample.Makespan else 0.0);
         Current.Total := (if Sane (Sample.Total) then Sample.Total else 0.0);
         Current.Round_Robots := Sample.Robots;
         declare
            New_Tasks : Task_View_Vectors.Vector;
         begin
            for T of Sample.Tasks loop
               if T.Points.Is_Empty or else T.Points.Length > Max_Points
                 or else (for some P of T.Points => not Sane (P))
               then
                  Reject ("a task with no points, too many or out of range ("
                          & To_String (Cut (T.Id)) & ")");
               else
                  declare
                     Old : constant Natural := Find_Task (Current, To_String (T.Id));
                     V   : Task_View :=
                       (Id     => Cut (T.Id),
                        Kind   => Cut (T.Kind),
                        Points => T.Points,
                        Choice => (if T.Choice <= Natural (T.Points.Length) then T.Choice
                                   else 0),
                        State  => Parse_State (To_String (T.State)),
                        Robot  => Cut (T.Robot));
                  begin
                     if Old > 0 and then Current.Tasks (Old).State = Done and then V.State /= Done
                     then
                        V.State := Done;
                        V.Robot := Current.Tasks (Old).Robot;
                        --  Done stays done (a replica lagging behind).
                     elsif V.State = Done
                       and then (Old = 0 or else Current.Tasks (Old).State /= Done)
                     then
                        Add_Event (To_String (V.Robot) & " did " & To_String (V.Id));
                     end if;
                     New_Tasks.Append (V);
                  end;
               end if;
            end loop;
            Current.Tasks := New_Tasks;
         end;
         if Current.Round /= Old_Round and then Old_Round = 0 then
            Round_Seen := 0.0;
            --  Joined while the round was under way: its planning time
            --  is unknown.
         end if;
         if Current.Round /= Old_Round then
            Add_Event ("round" & Current.Round'Image & ":" & Current.Round_Robots.Length'Image
                       & " robots," & Natural'Image (Natural (Current.Tasks.Length)
                                                     - Tasks_Done (Current)) & " tasks left");
            if Old_Round > 0 then
               Round_Seen := Elapsed;
            end if;
         end if;
         if Current.Plan_Round /= Old_Plan and then Current.Plan_Round = Current.Round then
            Add_Event ("round" & Current.Round'Image & " planned"
                       & (if Round_Seen > 0.0
                          then " in " & Image (Real (Elapsed - Round_Seen)) & " s" else "")
                       & " by " & To_String (Current.Proposer) & ": makespan "
                       & Image (Current.Makespan) & " m, total " & Image (Current.Total) & " m");
         end if;
         for Id of Current.Round_Robots loop
            if not In_Round.Contains (Id) then
               In_Round.Append (Id);
            end if;
         end loop;
         Current.Samples := Current.Samples + 1;
      end Update_Plan;

      procedure Update_Scan (Robot : String; Hits : Point_Vectors.Vector) is
      begin
         if not Current.Robots.Contains (Robot) then
            return;
         end if;
         declare
            R : Robot_View renames Current.Robots.Reference (Robot);
            C : constant Real := Cos (R.Where.Yaw);
            S : constant Real := Sin (R.Where.Yaw);
         begin
            R.Scan.Clear;
            for H of Hits loop
               if Sane (H) then
                  R.Scan.Append
                    (Point'(R.Where.X + C * H.X - S * H.Y, R.Where.Y + S * H.X + C * H.Y));
               end if;
            end loop;
         end;
      end Update_Scan;

      procedure Sim_Event (Text : String) is
         function Word (N : Positive) return String is
            First : Positive := Text'First;
            Count : Natural := 0;
         begin
            for K in Text'Range loop
               if Text (K) = ' ' or else K = Text'Last then
                  Count := Count + 1;
                  if Count = N then
                     return Text (First .. (if Text (K) = ' ' then K - 1 else K));
                  end if;
                  First := K + 1;
               end if;
            end loop;
            return "";
         end Word;
         What : constant String := Word (1);
         Who  : constant String := Word (2);
      begin
         if Text'Length > 200 then
            Reject ("a simulator event longer than 200 characters");
            return;
         end if;
         Add_Event ("sim: " & Text);
         if Current.Robots.Contains (Who) then
            declare
               R : Robot_View renames Current.Robots.Reference (Who);
            begin
               if What = "killed" then
                  R.Killed := True;
                  if not R.Lost then
                     R.Lost := True;
                     Add_Event (Who & " lost (killed in the simulator)");
                  end if;
               elsif What in "revived" | "added" then
                  R.Killed := False;
               end if;
            end;
         end if;
      end Sim_Event;

      procedure Set_Map (Map : Grid_Access) is
      begin
         Current.Map := Map;
         Current.Map_Version := Current.Map_Version + 1;
      end Set_Map;

      procedure Refresh is
         Now      : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
         Finished : constant Boolean :=
           not Current.Tasks.Is_Empty
           and then Tasks_Done (Current) = Natural (Current.Tasks.Length);
         --  Once the mission is done, the robots' agents end: not a loss.
      begin
         if Finished and then not Mission_Over then
            Mission_Over := True;
            Add_Event ("every task is done");
         end if;
         for R of Current.Robots loop
            if not R.Lost then
               if not Finished
                 and then Now - R.Last_Heard > Ada.Real_Time.To_Time_Span (Lost_After)
               then
                  R.Lost := True;
                  Add_Event (To_String (R.Id) & " lost (silent for " & Image (Real (Lost_After))
                             & " s)");
               elsif Left_Out (To_String (R.Id)) then
                  R.Lost := True;
                  Add_Event (To_String (R.Id) & " lost (left out of round" & Current.Round'Image
                             & " by the team)");
               end if;
            end if;
         end loop;
      end Refresh;

      function Get return Scene is
      begin
         return Result : Scene := Current do
            Result.Age := Elapsed;
         end return;
      end Get;

   end Store;

end Sancta.Views.Scenes;
