with Ada.Strings.Unbounded;
with ROSIDL.Interfaces;

package body ROSIDL.Typesupport is

   use ROSIDL.Definitions;
   use Ada.Strings.Unbounded;

   function Get_Message_Support
     (Package_Name, Message_Name : String) return Message_Support is
     ((Definition => ROSIDL.Interfaces.Message (Package_Name, Message_Name)));

   function To_Support
     (Definition : not null ROSIDL.Definitions.Message_Access)
      return Message_Support is ((Definition => Definition));

   function Definition
     (Support : Message_Support) return ROSIDL.Definitions.Message_Access is
   begin
      if Support.Definition = null then
         raise Program_Error with "uninitialised Message_Support";
      end if;
      return Support.Definition;
   end Definition;

   function DDS_Type_Name (Support : Message_Support) return String is
     (DDS_Type_Name (Definition (Support).all));

   function Full_Name (Support : Message_Support) return String is
     (Full_Name (Definition (Support).all));

   function Get_Service_Support
     (Package_Name, Service_Name : String) return Service_Support is
     ((Definition => ROSIDL.Interfaces.Service (Package_Name, Service_Name)));

   function To_Support
     (Definition : not null ROSIDL.Definitions.Service_Access)
      return Service_Support is ((Definition => Definition));

   function Service (Support : Service_Support) return Service_Access is
   begin
      if Support.Definition = null then
         raise Program_Error with "uninitialised Service_Support";
      end if;
      return Support.Definition;
   end Service;

   function Request_Support (Support : Service_Support) return Message_Support is
     ((Definition => Service (Support).Request));

   function Response_Support (Support : Service_Support) return Message_Support is
     ((Definition => Service (Support).Response));

   function Full_Name (Support : Service_Support) return String is
     (To_String (Service (Support).Package_Name)
      & (if Service (Support).Request.Namespace = Action then "/action/" else "/srv/")
      & To_String (Service (Support).Name));

end ROSIDL.Typesupport;
