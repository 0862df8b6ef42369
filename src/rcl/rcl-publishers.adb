with RCL.Contexts;

package body RCL.Publishers is

   use Ada.Strings.Unbounded;

   procedure Publish_Raw (This : Publisher; Data : RCL.DDS.Byte_Array) is
   begin
      if RCL.Contexts.Is_Shutdown then
         raise ROS_Exception with "publishing on " & Topic (This) & ": the context is shut down";
      end if;
      RCL.DDS.Write (This.W, Data);
   end Publish_Raw;

   function Topic (This : Publisher) return String is (To_String (This.Topic));

   function Type_Name (This : Publisher) return String is (RCL.DDS.Type_Name (This.W));

   function GID (This : Publisher) return RCL.DDS.GUID is (RCL.DDS.Endpoint_GUID (This.W));

   function Matched_Subscriptions (This : Publisher) return Natural is
     (RCL.DDS.Matched_Readers (This.W));

   procedure Create
     (This       : in out Publisher;
      Topic      : String;
      Type_Name  : String;
      Profile    : RCL.QoS.Profile;
      DDS_Topic  : String) is
   begin
      RCL.DDS.Create (This.W, RCL.Contexts.Participant.all, DDS_Topic, Type_Name, Profile);
      This.Topic := To_Unbounded_String (Topic);
   end Create;

   function Writer (This : Publisher) return access constant RCL.DDS.Writer is
     (This.W'Unchecked_Access);

end RCL.Publishers;
