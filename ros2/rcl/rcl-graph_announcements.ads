--  The process's announcement on ros_discovery_info (see RCL.Graph): the
--  nodes and their endpoints, republished whole on every change. Kept by
--  the units that make nodes and endpoints (RCL.Nodes, RCL.Publishers,
--  services, clients); a private child of RCL.
with RCL.DDS;
with RCL.Graph;

private package RCL.Graph_Announcements is

   procedure Add_Node (Namespace, Name : String; Id : out RCL.Graph.Node_Id);
   procedure Remove_Node (Id : RCL.Graph.Node_Id);
   procedure Add_Writer (Id : RCL.Graph.Node_Id; Endpoint : RCL.DDS.GUID);
   procedure Remove_Writer (Id : RCL.Graph.Node_Id; Endpoint : RCL.DDS.GUID);
   procedure Add_Reader (Id : RCL.Graph.Node_Id; Endpoint : RCL.DDS.GUID);
   procedure Remove_Reader (Id : RCL.Graph.Node_Id; Endpoint : RCL.DDS.GUID);
   --  Each change republishes the participant's entities. Errors while
   --  publishing are logged, never raised (graph presence is best effort).

   function Announcement return RCL.DDS.Byte_Array;
   --  The ParticipantEntitiesInfo sample last published (CDR), empty before
   --  the first node (for tests and diagnostics).

end RCL.Graph_Announcements;
