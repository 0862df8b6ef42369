--  Type support: what a publisher, subscription, service or client needs to
--  know about its interface type (its definition and its DDS type name).
--  Named as in RCLAda:
--  Example:
--     Support : constant Message_Support :=
--       ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");
--     Put_Line (DDS_Type_Name (Support));  --  std_msgs::msg::dds_::String_
with ROSIDL.Definitions;

package ROSIDL.Typesupport is

   use type ROSIDL.Definitions.Message_Access;

   type Message_Support is private;
   --  A handle on one message type; cheap to copy.

   function Get_Message_Support
     (Package_Name, Message_Name : String) return Message_Support;
   --  Raises Unknown_Type or Definition_Error (see ROSIDL.Interfaces).

   function To_Support
     (Definition : not null ROSIDL.Definitions.Message_Access)
      return Message_Support;
   --  Support for a definition obtained otherwise (e.g. a service part).

   function Definition
     (Support : Message_Support) return ROSIDL.Definitions.Message_Access
     with Post => Definition'Result /= null;

   function DDS_Type_Name (Support : Message_Support) return String;
   --  "std_msgs::msg::dds_::String_"

   function Full_Name (Support : Message_Support) return String;
   --  "std_msgs/msg/String"

   type Service_Support is private;

   function Get_Service_Support
     (Package_Name, Service_Name : String) return Service_Support;

   function To_Support
     (Definition : not null ROSIDL.Definitions.Service_Access)
      return Service_Support;
   --  Support for a service obtained otherwise (e.g. the SendGoal and
   --  GetResult services of an action).

   function Request_Support (Support : Service_Support) return Message_Support;
   function Response_Support (Support : Service_Support) return Message_Support;

   function Full_Name (Support : Service_Support) return String;
   --  "example_interfaces/srv/AddTwoInts" ("pkg/action/Name_SendGoal" for
   --  the services of an action).

private

   type Message_Support is record
      Definition : ROSIDL.Definitions.Message_Access;
   end record;

   type Service_Support is record
      Definition : ROSIDL.Definitions.Service_Access;
   end record;

end ROSIDL.Typesupport;
