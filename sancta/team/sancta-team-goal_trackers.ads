--  What a robot's team_member component does each period with the goal
--  its agent gives (Agents.Current_Goal): send a new goal downstream, stand
--  still (idle), report an arrival, or nothing. Kept apart from the
--  component (which needs DDS) so that the rule can be tested alone.
--
--     Tracker : Goal_Tracker;
--     case Tracker.Decide (Found, Goal, Task_Id, Here, Tolerance => 0.3) is
--        when New_Goal => Output the goal;
--        when Go_Idle  => Output "stand still";
--        when At_Goal  => Agent.Arrived (Task_Id, Done);
--        when Nothing  => null;
--     end case;
--
--  The rule: a goal is sent again whenever it is not the one the robot
--  was last sent, INCLUDING after an idle spell. (The stall of the team
--  demo: a new round leaves a robot without a plan for a moment, so it
--  was sent "stand still"; the new plan gave it back the same task and
--  point, which compared equal to the last goal sent before the idle spell,
--  so the goal was never sent again and the robot stood still for ever.)
with Ada.Strings.Unbounded;
with Sancta.Geometry;

package Sancta.Team.Goal_Trackers is

   use Sancta.Geometry;

   type Action is (Nothing, New_Goal, Go_Idle, At_Goal);

   type Goal_Tracker is tagged private;
   --  Initially nothing was sent (the first goal is new; the first "no
   --  goal" makes the robot idle).

   function Decide
     (This      : in out Goal_Tracker;
      Found     : Boolean;
      Goal      : Point;
      Task_Id   : String;
      Here      : Point;
      Tolerance : Real) return Action;
   --  Found, Goal, Task_Id as Current_Goal gave them, Here the robot's
   --  position. Not Found: Go_Idle once (then Nothing until a goal comes).
   --  Found within Tolerance of Goal: At_Goal. Otherwise New_Goal when the
   --  goal or the task differs from what was last sent or the robot was
   --  sent idle since, else Nothing.

   function Is_Idle (This : Goal_Tracker) return Boolean;
   --  The last thing sent was "stand still".

private

   type State is (Unknown, Idle, Going);

   type Goal_Tracker is tagged record
      Current : State := Unknown;
      Sent    : Point := (0.0, 0.0);
      Task_Id : Ada.Strings.Unbounded.Unbounded_String;
   end record
     with Type_Invariant =>
       Goal_Tracker.Current = Going
       or else Ada.Strings.Unbounded.Length (Goal_Tracker.Task_Id) = 0;
   --  Only a robot sent somewhere holds a task: going idle forgets it, so
   --  that the same task given back after an idle spell is sent again.

   function Is_Idle (This : Goal_Tracker) return Boolean is (This.Current = Idle);

end Sancta.Team.Goal_Trackers;
