--  Task execution: a robot's task list (goals to visit in order) turned
--  into successive goals, with completion detection and progress. Feed it
--  the robot's pose; it advances when the current goal is within the
--  tolerance.
--
--     E.Assign ([(2.0, 1.0), (5.0, 4.0)]);
--     loop
--        E.Update (Pose);
--        exit when E.Is_Done;
--        Drive_To (E.Current_Goal);
--     end loop;
with Ada.Containers.Vectors;
with Sancta.Geometry;  use Sancta.Geometry;

package Sancta.Robot.Goal_Sequencers is

   type Point_Array is array (Positive range <>) of Point;

   type Sequencer is tagged private;

   procedure Assign
     (This      : in out Sequencer;
      Goals     : Point_Array;
      Tolerance : Real := 0.2);
   --  Replaces the task list; progress restarts.

   procedure Append (This : in out Sequencer; Goal : Point);

   procedure Update (This : in out Sequencer; Current : Pose);
   --  Marks the current goal (and any next one already within reach) done.

   procedure Skip (This : in out Sequencer)
     with Pre => This.Has_Goal;
   --  Gives up the current goal (it counts as finished, and as skipped).

   function Skipped (This : Sequencer) return Natural;

   function Total (This : Sequencer) return Natural;
   function Completed (This : Sequencer) return Natural;
   --  Goals finished (reached or skipped).
   function Is_Done (This : Sequencer) return Boolean is
     (This.Completed = This.Total);
   function Has_Goal (This : Sequencer) return Boolean is (not This.Is_Done);

   function Current_Goal (This : Sequencer) return Point
     with Pre => This.Has_Goal;

   function Goal_Index (This : Sequencer) return Positive
     with Pre => This.Has_Goal;
   --  Position of the current goal in the task list.

   function Progress (This : Sequencer) return Real
     with Post => Progress'Result in 0.0 .. 1.0;
   --  Completed / Total (1 for an empty list).

private

   package Point_Vectors is new Ada.Containers.Vectors (Positive, Point);

   type Sequencer is tagged record
      Goals     : Point_Vectors.Vector;
      Done      : Natural := 0;
      Skips     : Natural := 0;
      Tolerance : Real := 0.2;
   end record
     with Type_Invariant =>
       Sequencer.Done <= Natural (Sequencer.Goals.Length)
       and then Sequencer.Skips <= Sequencer.Done;
   --  Goals finished never outnumber the goals; skipped ones are finished.

end Sancta.Robot.Goal_Sequencers;
