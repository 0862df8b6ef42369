--  Recording live topics into a bag, as "ros2 bag record": the topics to
--  record (or every topic) are looked up on the graph, including types this
--  process has never seen (the type name comes from discovery, the schema
--  from the interface definitions when they are on the path); each is
--  subscribed with the QoS its publishers offer (best effort when one of
--  them is, transient local when all of them are), keeping all samples
--  (a reliable publisher waits for the recorder rather than lose one), and
--  its serialized messages are written as they arrive (taken from DDS in
--  batches, RCL.DDS.Take_Many), stamped with their reception time; full
--  chunks are compressed and written by a task of the bag writer's own.
--  Example:
--     Node : Nodes.Node := Nodes.Init ("recorder");
--     Rec  : Recorder;
--     Rec.Start ("out/run", Topics => All_Topics);
--     loop
--        Rec.Discover (Node);         --  subscribe to topics that appeared
--        Node.Spin (During => 0.5);   --  messages are written here
--     end loop;
--     Rec.Stop;                       --  closes the bag (metadata.yaml)
with Ada.Finalization;
with ROSIDL.Definitions;
with RCL.Nodes;
private with ROSIDL.Mutexes;

package RCL.Bags.Recorders is

   subtype Topic_List is ROSIDL.Definitions.String_Vectors.Vector;

   All_Topics : constant Topic_List := ROSIDL.Definitions.String_Vectors.Empty_Vector;

   type Recorder is new Ada.Finalization.Limited_Controlled with private;

   procedure Start
     (This           : in out Recorder;
      Output         : String;
      Topics         : Topic_List := All_Topics;
      Compression    : RCL.MCAP.Compression_Kind := RCL.MCAP.Zstd;
      Max_Bytes      : Interfaces.Unsigned_64 := 0;
      Max_Duration   : Duration := 0.0;
      Include_Hidden : Boolean := False;
      Mode           : Bag_Compression := No_Compression);
   --  Creates the bag (Bag_Error when Output exists). Topics: names to
   --  record (relative ones are made absolute); empty: every topic except
   --  hidden ones (a name part starting with '_') unless Include_Hidden.
   --  Mode: rosbag2's zstd compression of files or messages (Create).

   procedure Discover (This : in out Recorder; Node : in out RCL.Nodes.Node'Class);
   --  Subscribes Node to each wanted topic that has a publisher on the graph
   --  and is not recorded yet. Call it after discovery has had a moment,
   --  then periodically while spinning Node.

   function Topic_Count (This : Recorder) return Natural;
   function Message_Count (This : Recorder) return Interfaces.Unsigned_64;

   procedure Stop (This : in out Recorder);
   --  Closes the bag. The node's subscriptions stay but write nothing more.

   overriding procedure Finalize (This : in out Recorder);

private

   subtype Lock is ROSIDL.Mutexes.Mutex;

   type State is limited record
      Bag       : Bag_Writer;
      Guard     : Lock;
      Recording : Boolean := False;
      Count     : Interfaces.Unsigned_64 := 0;
   end record;
   type State_Access is access State;

   type Recorder is new Ada.Finalization.Limited_Controlled with record
      Shared         : State_Access;
      Wanted         : Topic_List;
      Recorded       : Topic_List;
      Include_Hidden : Boolean := False;
   end record;

end RCL.Bags.Recorders;
