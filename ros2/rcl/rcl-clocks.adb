with Ada.Real_Time;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Arguments;
with RCL.DDS;
with RCL.Nodes;
with RCL.Process_Context;
with RCL.QoS;

package body RCL.Clocks is

   protected Sim is
      procedure Enable (Was : out Boolean);
      function Enabled return Boolean;
      procedure Set (T : Nanoseconds);
      function Get return Nanoseconds;
   private
      On   : Boolean := False;
      Time : Nanoseconds := 0;
   end Sim;

   protected body Sim is
      procedure Enable (Was : out Boolean) is
      begin
         Was := On;
         On := True;
      end Enable;
      function Enabled return Boolean is (On);
      procedure Set (T : Nanoseconds) is
      begin
         Time := T;
      end Set;
      function Get return Nanoseconds is (Time);
   end Sim;

   function Now (Kind : Clock_Kind := ROS) return Nanoseconds is
   begin
      case Kind is
         when Steady =>
            declare
               use Ada.Real_Time;
               S  : Seconds_Count;
               TS : Time_Span;
            begin
               Split (Clock, S, TS);
               return Nanoseconds (S) * 1_000_000_000
                 + Nanoseconds (To_Duration (TS) * 1_000_000_000.0);
            end;
         when System =>
            return Nanoseconds (RCL.DDS.Now);
         when ROS =>
            return (if Sim.Enabled then Sim.Get else Nanoseconds (RCL.DDS.Now));
      end case;
   end Now;

   function To_Duration (Span : Nanoseconds) return Duration is
     (Duration (Span / 1_000_000_000) + Duration (Span rem 1_000_000_000) / 1_000_000_000);

   procedure Set_Sim_Time (Time : Nanoseconds);
   --  What each /clock message does.

   procedure Set_Sim_Time (Time : Nanoseconds) is
   begin
      Sim.Set (Time);
      RCL.Process_Context.Wake_Executors;
      --  Their timers on simulated time may be due now.
   end Set_Sim_Time;

   function Sim_Time_Enabled return Boolean is (Sim.Enabled);

   procedure On_Clock
     (Node : in out RCL.Nodes.Node'Class;
      Msg  : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Set_Sim_Time
        (Nanoseconds (ROSIDL.Int32'(Msg ("clock") ("sec").As_Int32)) * 1_000_000_000
         + Nanoseconds (ROSIDL.UInt32'(Msg ("clock") ("nanosec").As_UInt32)));
   end On_Clock;

   procedure Subscribe_To_Clock (Node : in out RCL.Nodes.Node'Class) is
   begin
      Node.Subscribe
        (ROSIDL.Typesupport.Get_Message_Support ("rosgraph_msgs", "Clock"),
         "/clock", On_Clock'Access, RCL.QoS.Clock);
   end Subscribe_To_Clock;

   procedure Enable_Sim_Time (Node : in out RCL.Nodes.Node'Class) is
      Was : Boolean;
   begin
      Sim.Enable (Was);
      if not Was then
         Subscribe_To_Clock (Node);
      end if;
   end Enable_Sim_Time;

   procedure Follow_Clock (Node : in out RCL.Nodes.Node'Class) is
      Was : Boolean;
   begin
      Sim.Enable (Was);
      Subscribe_To_Clock (Node);
   end Follow_Clock;

   function Sim_Time_Requested return Boolean is
      Requested : Boolean := False;

      procedure Check (Flag, Value : String) is
      begin
         if Flag in "-p" | "--param"
           and then Value in "use_sim_time:=true" | "use_sim_time:=True"
         then
            Requested := True;
         end if;
      end Check;
   begin
      RCL.Arguments.For_Each_Parameter_Argument (Check'Access);
      return Requested;
   end Sim_Time_Requested;

end RCL.Clocks;
