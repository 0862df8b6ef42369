with Ada.Unchecked_Deallocation;
with RCL.Graph_Announcements;
with RCL.Names;
with RCL.Nodes;
with RCL.Process_Context;

package body RCL.Node_Entities is

   use type Ada.Real_Time.Time;

   protected body Registry is

      procedure Add (S : Subscription_Access) is
      begin
         if N_Sub = Max_Subscriptions then
            raise ROS_Exception with "more than" & Max_Subscriptions'Image
              & " subscriptions in one node";
         end if;
         N_Sub := N_Sub + 1;
         Subs (N_Sub) := S;
         Ver := Ver + 1;
      end Add;

      procedure Add (T : Timer_Entry) is
      begin
         if N_Tim = Max_Timers then
            raise ROS_Exception with "more than" & Max_Timers'Image & " timers in one node";
         end if;
         N_Tim := N_Tim + 1;
         Tims (N_Tim) := T;
         Ver := Ver + 1;
      end Add;

      function Version return Natural is (Ver);
      function Sub_Count return Natural is (N_Sub);
      function Sub (I : Positive) return Subscription_Access is (Subs (I));
      function Tim_Count return Natural is (N_Tim);
      function Tim (I : Positive) return Timer_Entry is (Tims (I));

      procedure Take_All (Subs : out Subscription_Array; N_Subs : out Natural;
                          Tims : out Timer_Array; N_Tims : out Natural) is
      begin
         Subs := Registry.Subs;
         N_Subs := N_Sub;
         Tims := Registry.Tims;
         N_Tims := N_Tim;
         N_Sub := 0;
         N_Tim := 0;
         Ver := Ver + 1;
      end Take_All;

   end Registry;

   --  Every node is a Node_Core (the full view of RCL.Nodes.Node extends
   --  it); Limited_Controlled is the ancestor both views show.
   function Core (Node : RCL.Nodes.Node'Class) return not null access constant Node_Core'Class
   is
     (Node_Core'Class (Ada.Finalization.Limited_Controlled'Class (Node))'Unchecked_Access);

   function Variable_Core
     (Node : in out RCL.Nodes.Node'Class) return not null access Node_Core'Class
   is
     (Node_Core'Class (Ada.Finalization.Limited_Controlled'Class (Node))'Unchecked_Access);

   function Graph_Id (Node : RCL.Nodes.Node'Class) return RCL.Graph.Node_Id is
     (Core (Node).Graph_Id);

   function Version (Node : RCL.Nodes.Node'Class) return Natural is
     (Core (Node).Entities.Version);

   function Subscription_Count (Node : RCL.Nodes.Node'Class) return Natural is
     (Core (Node).Entities.Sub_Count);

   function Get_Subscription
     (Node : RCL.Nodes.Node'Class; Index : Positive) return Subscription_Access is
     (Core (Node).Entities.Sub (Index));

   function Find_Subscription
     (Node : RCL.Nodes.Node'Class; Topic : String) return Subscription_Access
   is
      C : constant not null access constant Node_Core'Class := Core (Node);
   begin
      for I in 1 .. C.Entities.Sub_Count loop
         if C.Entities.Sub (I).Topic.all = Topic then
            return C.Entities.Sub (I);
         end if;
      end loop;
      return null;
   end Find_Subscription;

   function Timer_Count (Node : RCL.Nodes.Node'Class) return Natural is
     (Core (Node).Entities.Tim_Count);

   function Get_Timer (Node : RCL.Nodes.Node'Class; Index : Positive) return Timer_Entry is
     (Core (Node).Entities.Tim (Index));

   function Next_Timer_Due (Node : RCL.Nodes.Node'Class) return Ada.Real_Time.Time is
      C      : constant not null access constant Node_Core'Class := Core (Node);
      Result : Ada.Real_Time.Time := Ada.Real_Time.Time_Last;
   begin
      for I in 1 .. C.Entities.Tim_Count loop
         declare
            Due : constant Ada.Real_Time.Time := C.Entities.Tim (I).State.Due_At;
         begin
            if Due < Result then
               Result := Due;
            end if;
         end;
      end loop;
      return Result;
   end Next_Timer_Due;

   function Serves_Parameters (Node : RCL.Nodes.Node'Class) return Boolean is
     (Core (Node).Params_On);

   procedure Set_Serves_Parameters (Node : in out RCL.Nodes.Node'Class) is
   begin
      Variable_Core (Node).Params_On := True;
   end Set_Serves_Parameters;

   procedure Free is new Ada.Unchecked_Deallocation (Subscription, Subscription_Access);

   procedure Add_Endpoint
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      DDS_Topic : String;
      Name      : String;
      User_Data : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile;
      Added     : out Subscription_Access)
   is
      C : constant not null access Node_Core'Class := Variable_Core (Node);
      S : Subscription_Access := new Subscription;
      procedure Free_Name is new Ada.Unchecked_Deallocation (String, Name_Access);
   begin
      S.Topic := new String'(Name);
      S.Handle := Handle;
      S.Group := C.Current;
      RCL.DDS.Create (S.Reader, RCL.Process_Context.Participant.all, DDS_Topic, Type_Name, QoS,
                      User_Data => RCL.Graph.Endpoint_User_Data (Type_Name, User_Data));
      C.Entities.Add (S);
      RCL.Graph_Announcements.Add_Reader (C.Graph_Id, RCL.DDS.Endpoint_GUID (S.Reader));
      Added := S;
   exception
      when others =>
         if S /= null then
            Free_Name (S.Topic);
         end if;
         Free (S);
         raise;
   end Add_Endpoint;

   function Subscribe
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile) return Subscription_Access
   is
      FQ    : constant String := Node.Expand (Topic);
      Added : Subscription_Access;
   begin
      Add_Endpoint (Node, Type_Name, RCL.Names.DDS_Topic_Name (FQ), Name => FQ, User_Data => "",
                    Handle => Handle, QoS => QoS, Added => Added);
      return Added;
   end Subscribe;

   procedure Subscribe
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile)
   is
      FQ         : constant String := Node.Expand (Topic);
      Node_Owned : Subscription_Access;
      --  In Node's registry from here on (Add_Endpoint): nothing to keep.
   begin
      Add_Endpoint (Node, Type_Name, RCL.Names.DDS_Topic_Name (FQ), Name => FQ, User_Data => "",
                    Handle => Handle, QoS => QoS, Added => Node_Owned);
   end Subscribe;

   function To_Info (Info : RCL.DDS.Sample_Info) return ROSIDL.Message_Info is
     ((Source_Timestamp   => ROSIDL.Int64 (Info.Source_Timestamp),
       Received_Timestamp => ROSIDL.Int64 (RCL.DDS.Now),
       Publisher_GID      => ROSIDL.GID (Info.Publisher)));

end RCL.Node_Entities;
