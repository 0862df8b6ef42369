with RCL.DDS.Matching;
with RCL.Graph_Announcements;
with RCL.Node_Entities;
with RCL.Process_Context;
with RCL.Services;

package body RCL.Client_Endpoints is

   Deep_History : constant := 1000;
   --  The reply reader keeps at least this many replies: many calls in
   --  flight (tasks, asynchronous calls) must not push replies out of a
   --  KEEP_LAST history before they are taken. History depth does not
   --  affect matching.

   procedure Open_Endpoints
     (Node          : RCL.Nodes.Node'Class;
      Service_Name  : String;
      Request_Type  : String;
      Response_Type : String;
      QoS           : RCL.QoS.Profile;
      Requests      : in out RCL.DDS.Writer;
      Replies       : in out RCL.DDS.Reader;
      Handle        : out ROSIDL.UInt64)
   is
      P  : constant not null access RCL.DDS.Participant := RCL.Process_Context.Participant;
      Id : constant String := "clientid=" & RCL.DDS.Matching.New_Id (P.all) & ";";
   begin
      RCL.DDS.Create (Requests, P.all, RCL.Services.Request_Topic (Service_Name),
                      Request_Type, QoS,
                      User_Data => RCL.Graph.Endpoint_User_Data (Request_Type, Id));
      RCL.DDS.Create (Replies, P.all, RCL.Services.Reply_Topic (Service_Name),
                      Response_Type,
                      (QoS with delta Depth => Positive'Max (QoS.Depth, Deep_History)),
                      User_Data => RCL.Graph.Endpoint_User_Data (Response_Type, Id));
      Handle := RCL.DDS.Matching.Instance_Handle (Requests);
      RCL.Graph_Announcements.Add_Writer
        (RCL.Node_Entities.Graph_Id (Node), RCL.DDS.Endpoint_GUID (Requests));
      RCL.Graph_Announcements.Add_Reader
        (RCL.Node_Entities.Graph_Id (Node), RCL.DDS.Endpoint_GUID (Replies));
   end Open_Endpoints;

   procedure Close_Endpoints
     (Node     : RCL.Graph.Node_Id;
      Requests : RCL.DDS.Writer;
      Replies  : RCL.DDS.Reader) is
   begin
      RCL.Graph_Announcements.Remove_Writer (Node, RCL.DDS.Endpoint_GUID (Requests));
      RCL.Graph_Announcements.Remove_Reader (Node, RCL.DDS.Endpoint_GUID (Replies));
   end Close_Endpoints;

end RCL.Client_Endpoints;
