with RCL.Contexts;
with RCL.DDS.Matching;
with RCL.Graph_Announcements;
with RCL.Node_Entities;
with RCL.Process_Context;
with RCL.Services;

package body RCL.Client_Endpoints is

   use Ada.Real_Time;
   use Ada.Strings.Unbounded;

   Deep_History : constant := 1000;
   --  The reply reader keeps at least this many replies: many calls in
   --  flight (tasks, asynchronous calls) must not push replies out of a
   --  KEEP_LAST history before they are taken. History depth does not
   --  affect matching.

   procedure Open
     (This          : in out Endpoints;
      Node          : RCL.Nodes.Node'Class;
      Name          : String;
      Request_Type  : String;
      Response_Type : String;
      QoS           : RCL.QoS.Profile)
   is
      FQ : constant String := Node.Expand_Service (Name);
      P  : constant not null access RCL.DDS.Participant := RCL.Process_Context.Participant;
      Id : constant String := "clientid=" & RCL.DDS.Matching.New_Id (P.all) & ";";
   begin
      RCL.DDS.Create (This.Requests, P.all, RCL.Services.Request_Topic (FQ),
                      Request_Type, QoS,
                      User_Data => RCL.Graph.Endpoint_User_Data (Request_Type, Id));
      RCL.DDS.Create (This.Replies, P.all, RCL.Services.Reply_Topic (FQ),
                      Response_Type,
                      (QoS with delta Depth => Positive'Max (QoS.Depth, Deep_History)),
                      User_Data => RCL.Graph.Endpoint_User_Data (Response_Type, Id));
      This.Handle := RCL.DDS.Matching.Instance_Handle (This.Requests);
      This.Node := RCL.Node_Entities.Graph_Id (Node);
      RCL.Graph_Announcements.Add_Writer (This.Node, RCL.DDS.Endpoint_GUID (This.Requests));
      RCL.Graph_Announcements.Add_Reader (This.Node, RCL.DDS.Endpoint_GUID (This.Replies));
      RCL.DDS.Create (This.Waiting, P.all);
      RCL.DDS.Attach (This.Waiting, This.Replies, 1);
      This.Name := To_Unbounded_String (FQ);
      This.Is_Open := True;
   end Open;

   procedure Close (This : in out Endpoints) is
   begin
      if This.Is_Open then
         This.Is_Open := False;
         RCL.Graph_Announcements.Remove_Writer
           (This.Node, RCL.DDS.Endpoint_GUID (This.Requests));
         RCL.Graph_Announcements.Remove_Reader
           (This.Node, RCL.DDS.Endpoint_GUID (This.Replies));
      end if;
   exception
      when others =>
         null;  --  Finalization goes on; the entities are deleted anyway.
   end Close;

   function Service_Name (This : Endpoints) return String is (To_String (This.Name));

   function Service_Available (This : Endpoints) return Boolean is
     (RCL.DDS.Matching.Service_Available (This.Requests, This.Replies));

   function Available_Before (This : Endpoints; Deadline : Time) return Boolean is
   begin
      loop
         if Service_Available (This) then
            return True;
         end if;
         exit when Clock >= Deadline or else RCL.Contexts.Is_Shutdown;
         delay until (if Deadline < Clock + Milliseconds (10) then Deadline
                      else Clock + Milliseconds (10));
      end loop;
      return Service_Available (This);
   end Available_Before;

   procedure Await_Service (This : Endpoints; Deadline : Time; Timeout : Duration) is
   begin
      if not Available_Before (This, Deadline) then
         raise RCL_Timeout with "service " & Service_Name (This)
           & " not available after" & Seconds_Image (Timeout);
      end if;
   end Await_Service;

   function Deadline_Of (Timeout : Duration) return Time is
     (if Timeout >= 1.0E6 then Time_Last else Clock + To_Time_Span (Timeout));

   function Seconds_Image (Timeout : Duration) return String is
     (if Timeout >= 1.0E6 then "ever" else Duration'Image (Timeout) & " s");

end RCL.Client_Endpoints;
