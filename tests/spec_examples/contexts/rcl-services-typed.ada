with RCL.Services.Typed;
with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
use type Interfaces.Integer_64;
--  DECLARATIONS
Sum : Interfaces.Integer_64;
Sum_Response : ROSIDL.Static.Example_Interfaces.Services.AddTwoInts.Response.Message;
