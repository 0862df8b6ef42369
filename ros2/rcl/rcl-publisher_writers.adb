with RCL.Event_Watches;
with RCL.Graph_Announcements;
with RCL.Names;
with RCL.Process_Context;
with RCL.Publishers;

package body RCL.Publisher_Writers is

   --  Every publisher is a Publisher_Core (the full view of
   --  RCL.Publishers.Publisher extends it); Limited_Controlled is the
   --  ancestor both views show.
   function Core
     (This : RCL.Publishers.Publisher'Class) return not null access constant Publisher_Core'Class
   is
     (Publisher_Core'Class (Ada.Finalization.Limited_Controlled'Class (This))'Unchecked_Access);

   function Variable_Core
     (This : in out RCL.Publishers.Publisher'Class) return not null access Publisher_Core'Class
   is
     (Publisher_Core'Class (Ada.Finalization.Limited_Controlled'Class (This))'Unchecked_Access);

   procedure Create
     (This      : in out RCL.Publishers.Publisher'Class;
      Topic     : String;
      Type_Name : String;
      Profile   : RCL.QoS.Profile;
      Node      : RCL.Graph.Node_Id)
   is
      C : constant not null access Publisher_Core'Class := Variable_Core (This);
   begin
      RCL.DDS.Create (C.W, RCL.Process_Context.Participant.all, RCL.Names.DDS_Topic_Name (Topic),
                      Type_Name, Profile, User_Data => RCL.Graph.Endpoint_User_Data (Type_Name));
      C.Topic := Ada.Strings.Unbounded.To_Unbounded_String (Topic);
      C.Node := Node;
      RCL.Graph_Announcements.Add_Writer (Node, RCL.DDS.Endpoint_GUID (C.W));
      RCL.Event_Watches.Register_Publisher (RCL.Publishers.Publisher (This), Node);
   end Create;

   function Writer
     (This : RCL.Publishers.Publisher'Class) return not null access constant RCL.DDS.Writer is
     (Core (This).W'Access);

   procedure Set_Support
     (This    : in out RCL.Publishers.Publisher'Class;
      Support : ROSIDL.Typesupport.Message_Support)
   is
      C : constant not null access Publisher_Core'Class := Variable_Core (This);
   begin
      C.Support := Support;
      C.Typed := True;
   end Set_Support;

end RCL.Publisher_Writers;
