--  The two DDS endpoints of a service client -- request writer and reply
--  reader -- opened and announced in the graph, for the clients of
--  RCL.Clients and of RCL.Services.Typed. A private child of RCL.
with ROSIDL;
with RCL.DDS;
with RCL.Graph;
with RCL.Nodes;
with RCL.QoS;

private package RCL.Client_Endpoints is

   procedure Open_Endpoints
     (Node          : RCL.Nodes.Node'Class;
      Service_Name  : String;
      Request_Type  : String;
      Response_Type : String;
      QoS           : RCL.QoS.Profile;
      Requests      : in out RCL.DDS.Writer;
      Replies       : in out RCL.DDS.Reader;
      Handle        : out ROSIDL.UInt64)
     with Pre => not RCL.DDS.Is_Open (Requests) and then not RCL.DDS.Is_Open (Replies);
   --  The request writer and reply reader of a client of the fully
   --  qualified Service_Name with the DDS types given, with a new
   --  "clientid" in their USER_DATA, announced in the graph as endpoints of
   --  Node; Handle is the request writer's instance handle (the requests'
   --  header GUID).

   procedure Close_Endpoints
     (Node     : RCL.Graph.Node_Id;
      Requests : RCL.DDS.Writer;
      Replies  : RCL.DDS.Reader);
   --  Withdraws them from the graph of Node (RCL.Node_Entities.Graph_Id when they were
   --  opened); the DDS entities go with the objects.

end RCL.Client_Endpoints;
