--  Publishers: made by Node.Publish; publish messages on one topic.
--  Example:
--     Pub : Publishers.Publisher := Node.Publish (Support, "/chatter");
--     Pub.Publish (Msg);        --  a ROSIDL.Dynamic.Message of that type
--     Pub.Publish_Raw (Bytes);  --  CDR with the 4-byte encapsulation header
with Ada.Finalization;
with ROSIDL.Dynamic;
with RCL.DDS;

private with RCL.Publisher_Writers;

package RCL.Publishers is

   type Publisher is new Ada.Finalization.Limited_Controlled with private;

   procedure Publish_Raw (This : Publisher; Data : RCL.DDS.Byte_Array)
     with Pre => Data'Length >= 4;
   --  Publishes serialized bytes as they are. Raises ROS_Exception after
   --  the context has shut down, or on a DDS error.

   procedure Publish (This : in out Publisher; Msg : ROSIDL.Dynamic.Message);
   --  Serializes Msg (XCDR1, native byte order) and publishes it; raises
   --  ROS_Exception when Msg's type is not the publisher's, after shutdown,
   --  or on a DDS error; ROSIDL.Encode_Error when a bound is exceeded.

   function Topic (This : Publisher) return String;
   --  The fully qualified ROS topic name ("/chatter").

   function Type_Name (This : Publisher) return String;
   --  The DDS type name ("std_msgs::msg::dds_::String_").

   function GID (This : Publisher) return RCL.DDS.GUID;

   function Matched_Subscriptions (This : Publisher) return Natural;

   overriding procedure Finalize (This : in out Publisher);

private

   type Publisher is new RCL.Publisher_Writers.Publisher_Core with null record;
   --  The writer, topic, node and message type (RCL.Publisher_Writers).

end RCL.Publishers;
