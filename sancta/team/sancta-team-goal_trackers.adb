package body Sancta.Team.Goal_Trackers is

   use Ada.Strings.Unbounded;

   function Decide
     (This      : in out Goal_Tracker;
      Found     : Boolean;
      Goal      : Point;
      Task_Id   : String;
      Here      : Point;
      Tolerance : Real) return Action is
   begin
      if not Found then
         if This.Current = Idle then
            return Nothing;
         end if;
         This.Current := Idle;
         This.Task_Id := Null_Unbounded_String;
         return Go_Idle;
      elsif Distance (Here, Goal) <= Tolerance then
         return At_Goal;
      elsif This.Current /= Going or else Goal /= This.Sent
        or else To_String (This.Task_Id) /= Task_Id
      then
         This.Current := Going;
         This.Sent := Goal;
         This.Task_Id := To_Unbounded_String (Task_Id);
         return New_Goal;
      end if;
      return Nothing;
   end Decide;

end Sancta.Team.Goal_Trackers;
