with Ada.Containers.Vectors;
with RCL.Actions; use RCL.Actions;
with RCL.Actions.Servers; use RCL.Actions.Servers;
use ROSIDL.Dynamic;
use type Interfaces.Integer_32;
--  DECLARATIONS
package Goal_Vectors is new Ada.Containers.Vectors (Positive, Goal_Handle);
protected Pending is
   procedure Add (Goal : Goal_Handle);
private
   Goals : Goal_Vectors.Vector;
end Pending;
protected body Pending is
   procedure Add (Goal : Goal_Handle) is
   begin
      Goals.Append (Goal);
   end Add;
end Pending;
Server   : RCL.Actions.Servers.Server;
Goal     : Goal_Handle;
Feedback : Message;
Result   : Message;
