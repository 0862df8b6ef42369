with Ada.Containers.Vectors;

package body Stepped_Goals is

   package Work_Vectors is new Ada.Containers.Vectors (Positive, Work);

   Running : Work_Vectors.Vector;
   --  Touched by the callbacks only, all run by the one task spinning.

   procedure Add (W : Work) is
   begin
      Running.Append (W);
   end Add;

   procedure Step
     (Node    : in out RCL.Nodes.Node'Class;
      Timer   : in out RCL.Timers.Timer;
      Elapsed : Duration)
   is
      pragma Unreferenced (Timer, Elapsed);
      I    : Positive := 1;
      Done : Boolean;
   begin
      while I <= Natural (Running.Length) loop
         Advance (Node, Running.Reference (I), Done);
         if Done then
            Running.Delete (I);
         else
            I := I + 1;
         end if;
      end loop;
   end Step;

end Stepped_Goals;
