--  The components and listeners measured by Bench_Runtime.
with Ada.Real_Time;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Components;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Values;

package Bench_Runtime_Support is

   use Sancta.Runtime;

   type Micros_Array is array (Positive range <>) of Long_Float;

   Max_Samples : constant := 1_000_000;
   Samples     : access Micros_Array := new Micros_Array (1 .. Max_Samples);
   Samples_Count       : Natural := 0;
   --  Lateness of each activation of the Sampler, in microseconds.

   Period : constant Ada.Real_Time.Time_Span := Ada.Real_Time.Milliseconds (10);

   type Sampler is new Components.Component with null record;
   --  A 100 Hz component that records how late each Run starts.
   overriding procedure Run (This : in out Sampler; Next : in out Clocks.Time);

   type Counting is limited new Local_Databases.Listener with record
      N : Natural := 0;
   end record;
   overriding procedure On_Key_Stored
     (This : in out Counting; Key : String; Item : Values.Value'Class);
   overriding function Listener_Name (This : Counting) return String is ("counting");

end Bench_Runtime_Support;
