package body Bench_Runtime_Support is

   use type Ada.Real_Time.Time;

   overriding procedure Run (This : in out Sampler; Next : in out Clocks.Time) is
      Late : constant Ada.Real_Time.Time_Span := This.Now - Next;
   begin
      if Samples_Count < Max_Samples then
         Samples_Count := Samples_Count + 1;
         Samples (Samples_Count) := Long_Float (Ada.Real_Time.To_Duration (Late)) * 1.0E6;
      end if;
      Next := Next + Period;
   end Run;

   overriding procedure On_Key_Stored
     (This : in out Counting; Key : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Key, Item);
   begin
      This.N := This.N + 1;
   end On_Key_Stored;

end Bench_Runtime_Support;
