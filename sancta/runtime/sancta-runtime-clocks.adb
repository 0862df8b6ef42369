package body Sancta.Runtime.Clocks is

   use type Ada.Real_Time.Time;

   overriding function Now (This : Real_Clock) return Time is (Ada.Real_Time.Clock);

   overriding procedure Wait_Until (This : in out Real_Clock; Deadline : Time) is
   begin
      delay until Deadline;
   end Wait_Until;

   protected body Manual_Time is
      function Get return Time is (Current);

      procedure Move_To (T : Time) is
      begin
         if T > Current then
            Current := T;
         end if;
      end Move_To;
   end Manual_Time;

   overriding function Now (This : Manual_Clock) return Time is (This.Current.Get);

   overriding procedure Wait_Until (This : in out Manual_Clock; Deadline : Time) is
   begin
      This.Current.Move_To (Deadline);
   end Wait_Until;

   procedure Advance (This : in out Manual_Clock; By : Ada.Real_Time.Time_Span) is
   begin
      This.Current.Move_To (This.Current.Get + By);
   end Advance;

   function Epoch return Time is (Ada.Real_Time.Time_First + Ada.Real_Time.Seconds (3600));

end Sancta.Runtime.Clocks;
