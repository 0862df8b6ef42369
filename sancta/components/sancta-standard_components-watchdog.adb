with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Shutdown;

package body Sancta.Standard_Components.Watchdog is

   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;

   type Watchdog_Component is new Base_Component with record
      Timeout   : Ada.Real_Time.Time_Span;
      Check     : Ada.Real_Time.Time_Span;
      Abort_All : Boolean := True;
      Last_Seen : Clocks.Time;
      Alarmed   : Boolean := False;
   end record;

   overriding procedure Start (This : in out Watchdog_Component);
   overriding procedure Run (This : in out Watchdog_Component; Next : in out Clocks.Time);
   overriding procedure On_Input
     (This : in out Watchdog_Component; Data : String; Item : Values.Value'Class);

   function Seconds (Span : Ada.Real_Time.Time_Span) return String is
     (Values.Real_Image
        (Long_Float'Rounding (Long_Float (Ada.Real_Time.To_Duration (Span)) * 1000.0) / 1000.0));
   --  With millisecond precision.

   overriding procedure Start (This : in out Watchdog_Component) is
      Check : constant Long_Float := This.Option_Real ("check");
   begin
      This.Timeout := This.Option_Duration ("timeout");
      This.Check := (if Check > 0.0 then Ada.Real_Time.To_Time_Span (Duration (Check))
                     else This.Timeout / 4);
      if This.Check = Ada.Real_Time.Time_Span_Zero then
         This.Check := Ada.Real_Time.Milliseconds (1);
      end if;
      This.Abort_All := This.Option_Text ("action") = "abort";
      This.Last_Seen := This.Now;
      This.Subscribe ("watched");
   end Start;

   overriding procedure On_Input
     (This : in out Watchdog_Component; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data, Item);
   begin
      This.Last_Seen := This.Now;
      if This.Alarmed then
         This.Alarmed := False;
         This.Log (Logging.Info, "'" & This.Input_Key ("watched") & "' refreshed again");
         This.Output ("alarm", Values.Boolean_Value'(Data => False));
      end if;
   end On_Input;

   overriding procedure Run (This : in out Watchdog_Component; Next : in out Clocks.Time) is
      Age : constant Ada.Real_Time.Time_Span := This.Now - This.Last_Seen;
   begin
      if Age > This.Timeout and then not This.Alarmed then
         This.Alarmed := True;
         declare
            Message : constant String :=
              "'" & This.Input_Key ("watched") & "' not refreshed for " & Seconds (Age)
              & " s (timeout " & Seconds (This.Timeout) & " s)";
         begin
            if This.Abort_All then
               This.Log (Logging.Error, Message & ": aborting");
               Shutdown.Request ("watchdog " & This.Agent_Id & "/" & This.Name & ": " & Message,
                                 Failure => True);
            else
               This.Log (Logging.Warning, Message & ": alarm");
               This.Output ("alarm", Values.Boolean_Value'(Data => True));
            end if;
         end;
      end if;
      Next := Next + This.Check;
   end Run;

   function Create is new Factory.Create_Component (Watchdog_Component);

begin
   Factory.Register
     ((Name       => To_Unbounded_String ("watchdog"),
       Doc        => To_Unbounded_String ("aborts or raises an alarm when a key goes stale"),
       Ports      => Port_Vectors.Empty_Vector
                       & In_Port ("watched", Values.Any_Type, Doc => "the key watched")
                       & Out_Port ("alarm", "types.boolean", "true while stale"),
       Options    => Option_Vectors.Empty_Vector
                       & Make_Option ("timeout", Duration_Option, "5.0")
                       & Make_Option ("action", Choice_Option, "abort", Choices => "abort alarm")
                       & Make_Option ("check", Duration_Option, "0"),
       Any_Inputs => False,
       Refine     => null,
       others     => <>),
      Create'Access);
end Sancta.Standard_Components.Watchdog;
