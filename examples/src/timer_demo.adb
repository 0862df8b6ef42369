--  Timers on the node's clock and a Rate: a timer of PERIOD seconds prints
--  "tick N at T" (T: the node's ROS time, s); a Rate of 1/PERIOD Hz in a
--  task of its own prints "rate N at T". With --ros-args -p
--  use_sim_time:=true both follow /clock (they wait while it stands still).
--     timer_demo [PERIOD] [--ros-args ...]        (default 1.0)
with Ada.Text_IO;
with Example_Support; use Example_Support;
with RCL.Arguments;
with RCL.Clocks;
with RCL.Contexts;
with RCL.Nodes;
with RCL.Rates;
with RCL.Timers;

procedure Timer_Demo is

   use RCL;

   Ticks : Natural := 0;

   function Seconds return String is
     (Duration'Image (Clocks.To_Duration (Clocks.Now (Clocks.ROS))));

   procedure Tick
     (Node    : in out Nodes.Node'Class;
      Timer   : in out Timers.Timer;
      Elapsed : Duration)
   is
      pragma Unreferenced (Node, Timer, Elapsed);
   begin
      Ticks := Ticks + 1;
      Ada.Text_IO.Put_Line ("tick" & Ticks'Image & " at" & Seconds);
      Ada.Text_IO.Flush;
   end Tick;

begin
   RCL.Arguments.Load;
   declare
      Period : constant Duration := Duration'Value (Argument (1, "1.0"));
      Node   : Nodes.Node := Nodes.Init ("timer_demo");

      task Looper;
      task body Looper is
         R : Rates.Rate := Rates.Create (1.0 / Long_Float (Period), Clocks.ROS);
         N : Natural := 0;
      begin
         while R.Sleep or else not Contexts.Is_Shutdown loop
            exit when Contexts.Is_Shutdown;
            N := N + 1;
            Ada.Text_IO.Put_Line ("rate" & N'Image & " at" & Seconds);
            Ada.Text_IO.Flush;
         end loop;
      end Looper;
   begin
      Node.Timer_Add (Period, Tick'Access);
      Node.Spin;
   end;
exception
   when E : RCL.Arguments.Argument_Error | Constraint_Error =>
      Fail (E);
end Timer_Demo;
