package body Sancta.Robot.Goal_Sequencers is

   procedure Assign
     (This      : in out Sequencer;
      Goals     : Point_Array;
      Tolerance : Real := 0.2) is
   begin
      This.Goals.Clear;
      for G of Goals loop
         This.Goals.Append (G);
      end loop;
      This.Done := 0;
      This.Skips := 0;
      This.Tolerance := Tolerance;
   end Assign;

   procedure Append (This : in out Sequencer; Goal : Point) is
   begin
      This.Goals.Append (Goal);
   end Append;

   procedure Update (This : in out Sequencer; Current : Pose) is
   begin
      while This.Done < Natural (This.Goals.Length)
        and then Distance (Position (Current), This.Goals (This.Done + 1))
                   <= This.Tolerance
      loop
         This.Done := This.Done + 1;
      end loop;
   end Update;

   procedure Skip (This : in out Sequencer) is
   begin
      This.Done := This.Done + 1;
      This.Skips := This.Skips + 1;
   end Skip;

   function Skipped (This : Sequencer) return Natural is (This.Skips);

   function Total (This : Sequencer) return Natural is (Natural (This.Goals.Length));

   function Completed (This : Sequencer) return Natural is (This.Done);

   function Current_Goal (This : Sequencer) return Point is (This.Goals (This.Done + 1));

   function Goal_Index (This : Sequencer) return Positive is (This.Done + 1);

   function Progress (This : Sequencer) return Real is
     (if This.Goals.Is_Empty then 1.0
      else Real (This.Done) / Real (This.Goals.Length));

end Sancta.Robot.Goal_Sequencers;
