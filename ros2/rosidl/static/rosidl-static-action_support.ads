--  What every generated action package instantiates as Handling: the
--  message support of its goal, result and feedback, and its name. RCL's
--  typed action servers and clients (RCL.Actions.Typed) take an instance.
--  Example:
--     package Fib renames ROSIDL.Static.Example_Interfaces.Actions.Fibonacci;
--     Goal : Fib.Handling.Goal_Message := (Order => 10);
with ROSIDL.Static.Message_Support;

generic
   with package Goal_Handling is new ROSIDL.Static.Message_Support (<>);
   with package Result_Handling is new ROSIDL.Static.Message_Support (<>);
   with package Feedback_Handling is new ROSIDL.Static.Message_Support (<>);
   Full_Name : String;
   --  "example_interfaces/action/Fibonacci"
package ROSIDL.Static.Action_Support is

   subtype Goal_Message is Goal_Handling.Message;
   subtype Result_Message is Result_Handling.Message;
   subtype Feedback_Message is Feedback_Handling.Message;

end ROSIDL.Static.Action_Support;
