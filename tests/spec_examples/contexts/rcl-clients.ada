with RCL.Clients;
use type Interfaces.Integer_64;
use type RCL.Clients.Future_Return_Code;
--  DECLARATIONS
C       : Clients.Client;
Request : ROSIDL.Dynamic.Message;
Sum     : Interfaces.Integer_64;
procedure On_Sum (Response : ROSIDL.Dynamic.Message) is null;
