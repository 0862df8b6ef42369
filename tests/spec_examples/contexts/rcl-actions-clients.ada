with RCL.Actions; use RCL.Actions;
with RCL.Actions.Clients;
--  DECLARATIONS
package Clients renames RCL.Actions.Clients;
Goal   : ROSIDL.Dynamic.Message;
Result : ROSIDL.Dynamic.Message;
Id     : Goal_Id;
Status : Goal_Status;
Code   : Cancel_Code;
procedure On_Feedback (Node : in out Nodes.Node'Class; Goal : Goal_Id;
                       Feedback : ROSIDL.Dynamic.Message) is null;
procedure On_Status (Node : in out Nodes.Node'Class; Goal : Goal_Id;
                     Status : Goal_Status) is null;
