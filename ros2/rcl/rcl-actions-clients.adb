with Ada.Containers.Doubly_Linked_Lists;
with Ada.Containers.Ordered_Maps;
with Ada.Containers.Ordered_Sets;
with Ada.Containers.Vectors;
with Ada.Real_Time;
with Ada.Streams;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with ROSIDL.CDR;
with ROSIDL.Typesupport;
with RCL.Client_Endpoints;
with RCL.Contexts;
with RCL.DDS;
with RCL.Logging;
with RCL.QoS;

package body RCL.Actions.Clients is

   use ROSIDL.Dynamic;
   use type RCL.Node_Entities.Subscription_Access;

   --  The goals a client follows (see Goal lifetime in the spec).

   type Goal_Entry is record
      Status : Goal_Status := Unknown;
      --  As the status topic last gave it.
      Taken  : Boolean := False;
      --  Get_Result returned its result.
   end record;

   package Goal_Maps is new Ada.Containers.Ordered_Maps (Goal_Id, Goal_Entry);
   package Id_Sets is new Ada.Containers.Ordered_Sets (Goal_Id);

   type Lingering is record
      Id    : Goal_Id;
      Due   : Ada.Real_Time.Time;
   end record;
   package Linger_Lists is new Ada.Containers.Doubly_Linked_Lists (Lingering);

   protected type Goal_Set is
      procedure Add (Id : Goal_Id);
      --  Id's status is Unknown until the status topic names it.
      procedure Remove (Id : Goal_Id);
      function Contains (Id : Goal_Id) return Boolean;
      function Status (Id : Goal_Id) return Goal_Status;
      function Count return Natural;
      procedure Update (Id : Goal_Id; To : Goal_Status; Changed, Done : out Boolean);
      --  Id's status becomes To when Id is one of the set; Changed when it
      --  was another status; Done when To is terminal and the result was
      --  taken (the goal is to be removed, after the callbacks).
      procedure Result_Taken (Id : Goal_Id; Status : Goal_Status);
      --  Get_Result answered Status (terminal or Unknown) for Id.
      procedure Remove_Ended_Absent (Listed : Id_Sets.Set);
      --  Removes the goals whose status is terminal and that the status
      --  array just received (its goals: Listed) no longer names.
   private
      procedure Prune;
      --  Removes the goals whose result was taken Status_Linger ago.
      Goals   : Goal_Maps.Map;
      Waiting : Linger_Lists.List;
      --  Goals whose result was taken, oldest first.
   end Goal_Set;

   protected body Goal_Set is
      procedure Prune is
         Now : constant Ada.Real_Time.Time := Ada.Real_Time.Clock;
      begin
         while not Waiting.Is_Empty and then Ada.Real_Time."<=" (Waiting.First_Element.Due, Now)
         loop
            Goals.Exclude (Waiting.First_Element.Id);
            Waiting.Delete_First;
         end loop;
      end Prune;

      procedure Add (Id : Goal_Id) is
      begin
         Prune;
         Goals.Include (Id, (others => <>));
      end Add;

      procedure Remove (Id : Goal_Id) is
      begin
         Goals.Exclude (Id);
      end Remove;

      function Contains (Id : Goal_Id) return Boolean is (Goals.Contains (Id));

      function Status (Id : Goal_Id) return Goal_Status is
        (if Goals.Contains (Id) then Goals (Id).Status else Unknown);

      function Count return Natural is (Natural (Goals.Length));

      procedure Update (Id : Goal_Id; To : Goal_Status; Changed, Done : out Boolean) is
         C : constant Goal_Maps.Cursor := Goals.Find (Id);
      begin
         Changed := Goal_Maps.Has_Element (C) and then Goals (C).Status /= To;
         Done := Goal_Maps.Has_Element (C) and then Goals (C).Taken and then To in Terminal_Status;
         if Changed then
            Goals (C).Status := To;
         end if;
      end Update;

      procedure Result_Taken (Id : Goal_Id; Status : Goal_Status) is
         C : constant Goal_Maps.Cursor := Goals.Find (Id);
      begin
         Prune;
         if not Goal_Maps.Has_Element (C) or else Goals (C).Taken then
            null;
         elsif Status = Unknown or else Goals (C).Status in Terminal_Status then
            Goals.Delete (Id);
         else
            Goals (C).Taken := True;
            Waiting.Append
              ((Id, Ada.Real_Time."+" (Ada.Real_Time.Clock,
                                       Ada.Real_Time.To_Time_Span (Status_Linger))));
         end if;
      end Result_Taken;

      procedure Remove_Ended_Absent (Listed : Id_Sets.Set) is
         Gone : Id_Sets.Set;
      begin
         Prune;
         for C in Goals.Iterate loop
            if Goals (C).Status in Terminal_Status and then not Listed.Contains (Goal_Maps.Key (C))
            then
               Gone.Insert (Goal_Maps.Key (C));
            end if;
         end loop;
         for Id of Gone loop
            Goals.Delete (Id);
         end loop;
      end Remove_Ended_Absent;
   end Goal_Set;

   function Number (Code : Integer) return String is
     (Ada.Strings.Fixed.Trim (Code'Image, Ada.Strings.Left));

   function About_Another_Goal
     (Mine : Goal_Set_Access; Data : RCL.DDS.Byte_Array; Type_Name : String) return Boolean
   is
      --  The feedback's goal_id (its first field: 16 bytes, the same in
      --  either byte order) is not one of Mine, read before decoding the
      --  rest, so that a malformed feedback about another client's goal is
      --  not reported by this one. False when the id is cut short (the
      --  decoder then says where); Decode_Error naming Type_Name when the
      --  encapsulation header is unknown.
      use Ada.Streams;
      Order : constant ROSIDL.CDR.Byte_Order := ROSIDL.CDR.Byte_Order_Of (Data, Type_Name);
      pragma Unreferenced (Order);
      First : constant Stream_Element_Offset := Data'First + ROSIDL.CDR.Encapsulation_Size;
      Id    : Goal_Id;
   begin
      if Data'Length < ROSIDL.CDR.Encapsulation_Size + Goal_Id'Length then
         return False;
      end if;
      for I in Id'Range loop
         Id (I) := ROSIDL.UInt8 (Data (First + Stream_Element_Offset (I - Id'First)));
      end loop;
      return not Mine.Contains (Id);
   end About_Another_Goal;

   type Feedback_Handler is new RCL.Nodes.Handler with record
      Support  : Action_Support;
      Mine     : Goal_Set_Access;
      Callback : Feedback_Callback;
   end record;

   overriding procedure Deliver
     (This : in out Feedback_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Info);
      Support : constant ROSIDL.Typesupport.Message_Support :=
        Feedback_Message_Support (This.Support);
   begin
      if About_Another_Goal (This.Mine, Data, ROSIDL.Typesupport.Full_Name (Support)) then
         return;
      end if;
      declare
         Msg : constant Message := ROSIDL.CDR.Decode (Support, Data);
         Id  : constant Goal_Id := Get_Id (Msg ("goal_id"));
      begin
         if This.Mine.Contains (Id) then
            This.Callback (Node, Id, To_Message (Msg ("feedback")));
         end if;
      end;
   end Deliver;

   --  The status topic: every status array names the goals of the server
   --  (of every client); those of Mine are followed, the others ignored.

   type Status_Handler is new RCL.Nodes.Handler with record
      Action   : Ada.Strings.Unbounded.Unbounded_String;
      Mine     : Goal_Set_Access;
      Callback : Status_Callback;
   end record;

   type Status_Change is record
      Id : Goal_Id;
      To : Goal_Status;
   end record;

   package Change_Vectors is new Ada.Containers.Vectors (Positive, Status_Change);

   overriding procedure Deliver
     (This : in out Status_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Info);
      Msg     : constant Message := ROSIDL.CDR.Decode (Status_Support, Data);
      List    : constant Array_Ref := Msg ("status_list").As_Array;
      Changes : Change_Vectors.Vector;
      Done    : Id_Sets.Set;
      --  Goals ended whose result was taken.
      Listed  : Id_Sets.Set;
   begin
      --  Every entry first (an entry that is no status loses none of the
      --  others), then the callbacks, then the goals done are dropped.
      for I in 1 .. List.Length loop
         declare
            Item    : constant Field_Ref := List.Element (I);
            Id      : constant Goal_Id := Get_Id (Item ("goal_info")("goal_id"));
            Code    : constant Integer := Integer (Item ("status").As_Int8.Element.all);
            Changed, Ended : Boolean;
         begin
            Listed.Include (Id);
            if not This.Mine.Contains (Id) then
               null;  --  Another client's goal.
            elsif Code not in Goal_Status'Pos (Goal_Status'First)
                              .. Goal_Status'Pos (Goal_Status'Last)
            then
               RCL.Logging.Error
                 ("action " & Ada.Strings.Unbounded.To_String (This.Action)
                  & ": the status topic gives goal " & Image (Id) & " status " & Number (Code)
                  & ", which is no goal status (0 .. 6); entry" & I'Image & " of"
                  & List.Length'Image & " ignored, the goal stays "
                  & Status_Image (This.Mine.Status (Id)),
                  Logger => Node.Logger_Name);
            else
               This.Mine.Update (Id, Goal_Status'Val (Code), Changed, Ended);
               if Changed then
                  Changes.Append (Status_Change'(Id, Goal_Status'Val (Code)));
               end if;
               if Ended then
                  Done.Include (Id);
               end if;
            end if;
         end;
      end loop;
      if This.Callback /= null then
         for C of Changes loop
            This.Callback (Node, C.Id, C.To);
         end loop;
      end if;
      for Id of Done loop
         This.Mine.Remove (Id);
      end loop;
      This.Mine.Remove_Ended_Absent (Listed);
   end Deliver;

   procedure Init
     (This        : in out Client;
      Node        : in out RCL.Nodes.Node'Class;
      Support     : Action_Support;
      Name        : String;
      On_Feedback : access procedure
        (Node     : in out RCL.Nodes.Node'Class;
         Goal     : Goal_Id;
         Feedback : ROSIDL.Dynamic.Message) := null;
      On_Status   : access procedure
        (Node   : in out RCL.Nodes.Node'Class;
         Goal   : Goal_Id;
         Status : Goal_Status) := null)
   is
      Stored : constant Feedback_Callback with Import, Address => On_Feedback'Address;
      Stored_Status : constant Status_Callback with Import, Address => On_Status'Address;
      --  GNAT: the same subprogram accesses, kept beyond the call.
      FQ     : constant String := Node.Expand_Service (Name);
   begin
      This.Support := Support;
      This.Mine := new Goal_Set;
      This.Send.Init (Node, Send_Goal_Support (Support), FQ & Send_Goal_Suffix);
      This.Cancel.Init (Node, Cancel_Support, FQ & Cancel_Suffix);
      This.Results.Init (Node, Get_Result_Support (Support), FQ & Get_Result_Suffix);
      if Stored /= null then
         This.Feedback := RCL.Node_Entities.Subscribe
           (Node, ROSIDL.Typesupport.DDS_Type_Name (Feedback_Message_Support (Support)),
            FQ & Feedback_Suffix,
            new Feedback_Handler'(Support => Support, Mine => This.Mine, Callback => Stored),
            RCL.QoS.Default);
      end if;
      This.Statuses := RCL.Node_Entities.Subscribe
        (Node, ROSIDL.Typesupport.DDS_Type_Name (Status_Support),
         FQ & Status_Suffix,
         new Status_Handler'(Action   => Ada.Strings.Unbounded.To_Unbounded_String (FQ),
                             Mine     => This.Mine,
                             Callback => Stored_Status),
         RCL.QoS.Action_Status);
   end Init;

   function Name (This : Client) return String is
     (This.Send.Service_Name (This.Send.Service_Name'First
                              .. This.Send.Service_Name'Last - Send_Goal_Suffix'Length));

   function Status (This : Client; Id : Goal_Id) return Goal_Status is
     (if This.Mine = null then Unknown else This.Mine.Status (Id));

   function Follows (This : Client; Id : Goal_Id) return Boolean is
     (This.Mine /= null and then This.Mine.Contains (Id));

   function Followed_Goals (This : Client) return Natural is
     (if This.Mine = null then 0 else This.Mine.Count);

   procedure Forget (This : in out Client; Id : Goal_Id) is
   begin
      if This.Mine /= null then
         This.Mine.Remove (Id);
      end if;
   end Forget;

   function Matched (Sub : RCL.Node_Entities.Subscription_Access) return Boolean is
     (RCL.DDS.Matched_Writers (Sub.Reader) > 0);

   function Server_Available (This : Client) return Boolean is
     (This.Statuses /= null
      and then This.Send.Service_Available and then This.Cancel.Service_Available
      and then This.Results.Service_Available
      and then Matched (This.Statuses)
      and then (This.Feedback = null or else Matched (This.Feedback)));

   function Missing (This : Client) return String is
      --  What Server_Available lacks, as "send_goal service, status
      --  publisher"; "" when nothing.
      function Item (Absent : Boolean; What : String) return String is
        (if Absent then ", " & What else "");
      All_Of : constant String :=
        Item (not This.Send.Service_Available, "send_goal service")
        & Item (not This.Cancel.Service_Available, "cancel_goal service")
        & Item (not This.Results.Service_Available, "get_result service")
        & Item (not Matched (This.Statuses), "status publisher")
        & Item (This.Feedback /= null and then not Matched (This.Feedback),
                "feedback publisher");
   begin
      return All_Of (All_Of'First + (if All_Of = "" then 0 else 2) .. All_Of'Last);
   end Missing;

   procedure Wait_For_Server (This : Client; Timeout : Duration := Forever) is
      --  Polls every 10 ms (as RCL.Clients.Wait_For_Service does): the
      --  matches of three services and two subscriptions have no single
      --  event to wait on.
      use Ada.Real_Time;
      Deadline : constant Time := RCL.Client_Endpoints.Deadline_Of (Timeout);
   begin
      if This.Statuses = null then
         raise ROS_Exception with "Wait_For_Server of an action client not initialised";
      end if;
      while not Server_Available (This) loop
         if Clock >= Deadline or else RCL.Contexts.Is_Shutdown then
            declare
               Lacks : constant String := Missing (This);
            begin
               exit when Lacks = "";  --  Came just now.
               raise RCL_Timeout with "action " & This.Name & ": no server available after"
                 & RCL.Client_Endpoints.Seconds_Image (Timeout) & " (missing: " & Lacks & ")";
            end;
         end if;
         delay until (if Deadline < Clock + Milliseconds (10) then Deadline
                      else Clock + Milliseconds (10));
      end loop;
   end Wait_For_Server;

   procedure Send_Goal
     (This     : in out Client;
      Goal     : ROSIDL.Dynamic.Message;
      Id       : out Goal_Id;
      Accepted : out Boolean;
      Timeout  : Duration := 10.0)
   is
      Request : constant Message :=
        Init (ROSIDL.Typesupport.Request_Support (Send_Goal_Support (This.Support)));
   begin
      Id := New_Goal_Id;
      This.Mine.Add (Id);
      --  Before sending: the first feedback may come before the response.
      Put_Id (Request ("goal_id"), Id);
      Request ("goal").Set_Message (Goal);
      Accepted := Boolean (This.Send.Call (Request, Timeout) ("accepted").As_Bool.Element.all);
      if not Accepted then
         This.Mine.Remove (Id);  --  No status, no feedback will come.
      end if;
   end Send_Goal;

   function Send_Goal
     (This    : in out Client;
      Goal    : ROSIDL.Dynamic.Message;
      Timeout : Duration := 10.0) return Goal_Id
   is
      Accepted : Boolean;
   begin
      return Id : Goal_Id do
         This.Send_Goal (Goal, Id, Accepted, Timeout);
         if not Accepted then
            raise Goal_Rejected with "action " & This.Name & " rejected goal " & Image (Id);
         end if;
      end return;
   end Send_Goal;

   procedure Get_Result
     (This    : in out Client;
      Id      : Goal_Id;
      Status  : out Goal_Status;
      Result  : out ROSIDL.Dynamic.Message;
      Timeout : Duration := Forever)
   is
      Request  : constant Message :=
        Init (ROSIDL.Typesupport.Request_Support (Get_Result_Support (This.Support)));
   begin
      Put_Id (Request ("goal_id"), Id);
      declare
         Response : constant Message := This.Results.Call (Request, Timeout);
         Code     : constant Integer := Integer (Response ("status").As_Int8.Element.all);
      begin
         if Code not in Goal_Status'Pos (Goal_Status'First) .. Goal_Status'Pos (Goal_Status'Last)
         then
            raise ROS_Exception with "action " & This.Name & ": get_result answered status "
              & Number (Code) & ", which is no goal status (0 .. 6)";
         end if;
         Status := Goal_Status'Val (Code);
         Result := To_Message (Response ("result"));
      end;
      if Status = Unknown or else Status in Terminal_Status then
         This.Mine.Result_Taken (Id, Status);
      end if;
   end Get_Result;

   function Cancel
     (This : in out Client; Id : Goal_Id; Timeout : Duration) return Cancel_Code
   is
      Request : constant Message :=
        Init (ROSIDL.Typesupport.Request_Support (Cancel_Support));
   begin
      Put_Id (Request ("goal_info")("goal_id"), Id);
      declare
         Code : constant Integer :=
           Integer (This.Cancel.Call (Request, Timeout) ("return_code").As_Int8.Element.all);
      begin
         if Code not in Cancel_Code'Pos (Cancel_Code'First) .. Cancel_Code'Pos (Cancel_Code'Last)
         then
            raise ROS_Exception with "action " & This.Name & ": cancel_goal answered return code "
              & Number (Code) & ", which is no cancel code (0 .. 3)";
         end if;
         return Cancel_Code'Val (Code);
      end;
   end Cancel;

   function Cancel_Goal
     (This    : in out Client;
      Id      : Goal_Id;
      Timeout : Duration := 10.0) return Cancel_Code is (Cancel (This, Id, Timeout));

   function Cancel_All_Goals
     (This    : in out Client;
      Timeout : Duration := 10.0) return Cancel_Code is (Cancel (This, Null_Goal_Id, Timeout));

end RCL.Actions.Clients;
