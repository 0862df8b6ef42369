--  Publishers: made by Node.Publish; publish messages on one topic.
--
--     Pub : Publishers.Publisher := Node.Publish_Raw
--       ("std_msgs::msg::dds_::String_", "/chatter");
--     Pub.Publish_Raw (Bytes);  --  CDR with the 4-byte encapsulation header
with Ada.Finalization;
with RCL.DDS;
with RCL.QoS;

private with Ada.Strings.Unbounded;

package RCL.Publishers is

   type Publisher is new Ada.Finalization.Limited_Controlled with private;

   procedure Publish_Raw (This : Publisher; Data : RCL.DDS.Byte_Array)
     with Pre => Data'Length >= 4;
   --  Publishes serialized bytes as they are. Raises ROS_Exception after
   --  the context has shut down, or on a DDS error.

   function Topic (This : Publisher) return String;
   --  The fully qualified ROS topic name ("/chatter").

   function Type_Name (This : Publisher) return String;
   --  The DDS type name ("std_msgs::msg::dds_::String_").

   function GID (This : Publisher) return RCL.DDS.GUID;

   function Matched_Subscriptions (This : Publisher) return Natural;

   --  Not for users:
   procedure Create
     (This       : in out Publisher;
      Topic      : String;
      Type_Name  : String;
      Profile    : RCL.QoS.Profile;
      DDS_Topic  : String);

   function Writer (This : Publisher) return access constant RCL.DDS.Writer;

private

   type Publisher is new Ada.Finalization.Limited_Controlled with record
      W     : aliased RCL.DDS.Writer;
      Topic : Ada.Strings.Unbounded.Unbounded_String;
   end record;

end RCL.Publishers;
