with Ada.Exceptions;
with Ada.Real_Time;
with RCL.Clocks;
with RCL.Nodes;
with Sancta.Logging;
with Sancta.Runtime.Tasks;

package body Sancta.Standard_Components.ROS_Clocks is

   use type Ada.Real_Time.Time;

   overriding function Now (This : ROS_Clock) return Runtime.Clocks.Time is
     (Runtime.Clocks.Epoch + Ada.Real_Time.To_Time_Span
        (RCL.Clocks.To_Duration (RCL.Clocks.Now (RCL.Clocks.ROS))));

   overriding procedure Wait_Until (This : in out ROS_Clock; Deadline : Runtime.Clocks.Time) is
      Give_Up : constant Ada.Real_Time.Time :=
        Ada.Real_Time.Clock + Ada.Real_Time.To_Time_Span (Max_Wait);
   begin
      while This.Now < Deadline and then Ada.Real_Time.Clock < Give_Up loop
         delay 0.001;
      end loop;
   end Wait_Until;

   task body Spinner is
      Node : RCL.Nodes.Node := RCL.Nodes.Init (Ada.Strings.Unbounded.To_String (Owner.Name));
   begin
      RCL.Clocks.Follow_Clock (Node);
      --  Not Enable_Sim_Time: that subscribes to /clock only on the first
      --  node that enables it, which may be gone (another component, a
      --  test); this node subscribes too, so ROS time follows /clock while
      --  it lives.
      accept Ready;
      while not Owner.Stopping loop
         begin
            Node.Spin (During => 0.05);
         exception
            when E : others =>
               --  Keep following /clock: a dead spinner would freeze the time.
               Sancta.Logging.Log ("sim-time", Sancta.Logging.Error, "/clock: "
                                   & Ada.Exceptions.Exception_Information (E));
         end;
         delay 0.001;  --  Spin returns at once after a shutdown: do not busy-loop.
      end loop;
   end Spinner;

   procedure Follow_Clock_Topic (This : in out ROS_Clock; Node_Name : String := "sancta_clock")
   is
   begin
      if This.Worker = null then
         This.Name := Ada.Strings.Unbounded.To_Unbounded_String (Node_Name);
         This.Stopping := False;
         This.Worker := new Spinner (This'Unchecked_Access);
         This.Worker.Ready;
      end if;
   end Follow_Clock_Topic;

   procedure Stop (This : in out ROS_Clock) is
   begin
      This.Stopping := True;
      if This.Worker /= null then
         Runtime.Tasks.Await_Termination (This.Worker'Identity);
         This.Worker := null;
      end if;
   end Stop;

end Sancta.Standard_Components.ROS_Clocks;
