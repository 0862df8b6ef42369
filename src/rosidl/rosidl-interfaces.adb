--  TRANSITIONAL: the interface parser is being written (issue 2); until it
--  lands every look-up reports that no definition can be loaded yet.
package body ROSIDL.Interfaces is

   Not_Yet : constant String := "interface parser not built yet: ";

   procedure Add_Folder (Folder : String) is
   begin
      raise Definition_Error with Not_Yet & Folder;
   end Add_Folder;

   function Search_Path return String_Vectors.Vector is
     (String_Vectors.Empty_Vector);

   function Message (Package_Name, Name : String) return Message_Access is
   begin
      raise Unknown_Type with Not_Yet & Package_Name & "/msg/" & Name;
      return null;
   end Message;

   function Service (Package_Name, Name : String) return Service_Access is
   begin
      raise Unknown_Type with Not_Yet & Package_Name & "/srv/" & Name;
      return null;
   end Service;

   function Action (Package_Name, Name : String) return Action_Access is
   begin
      raise Unknown_Type with Not_Yet & Package_Name & "/action/" & Name;
      return null;
   end Action;

   function Message (Full_Name : String) return Message_Access is
   begin
      raise Unknown_Type with Not_Yet & Full_Name;
      return null;
   end Message;

   function Packages return String_Vectors.Vector is
     (String_Vectors.Empty_Vector);
   function Messages (Package_Name : String) return String_Vectors.Vector is
     (String_Vectors.Empty_Vector);
   function Services (Package_Name : String) return String_Vectors.Vector is
     (String_Vectors.Empty_Vector);
   function Actions (Package_Name : String) return String_Vectors.Vector is
     (String_Vectors.Empty_Vector);

end ROSIDL.Interfaces;
