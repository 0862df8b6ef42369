--  What every generated service package instantiates as Handling: its
--  request and response message types (ROSIDL.Static.Message_Support instances)
--  and its name. RCL's typed services and clients take an instance:
--  Example:
--     package Add renames ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
--     Request : Add.Request.Message := (A => 2, B => 3);
with ROSIDL.Static.Message_Support;

generic
   with package Request_Handling is new ROSIDL.Static.Message_Support (<>);
   with package Response_Handling is new ROSIDL.Static.Message_Support (<>);
   Full_Name : String;
   --  "example_interfaces/srv/AddTwoInts"
package ROSIDL.Static.Service_Support is

   subtype Request_Message is Request_Handling.Message;
   subtype Response_Message is Response_Handling.Message;

end ROSIDL.Static.Service_Support;
