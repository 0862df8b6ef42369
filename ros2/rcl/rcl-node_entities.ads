--  What the other RCL units reach inside a node: its subscriptions and
--  timers (the executors run them, services and the QoS event watches add
--  or find them), its identity in the graph announcements and whether its
--  parameter services run. The full view of RCL.Nodes.Node extends
--  Node_Core; the operations below take any node. A private child of RCL:
--  its users are RCL's bodies (and `private with` in RCL specs).
with Ada.Finalization;
with Ada.Real_Time;
with ROSIDL;
with RCL.DDS;
with RCL.Graph;
with RCL.QoS;
with RCL.Timer_States;
with RCL.Timers;
limited with RCL.Nodes;

private package RCL.Node_Entities is

   type Handler_Access is access all RCL.Nodes.Handler'Class;

   type Name_Access is access String;

   type Node_Serial is new Natural;
   --  Tells the nodes of a process apart (callback groups' owners).

   type Group_Data is record
      Owner     : Node_Serial := 0;
      --  0: the default group of any node.
      Id        : Natural := 0;
      --  0 for the default group, then 1, 2, ... per node.
      Exclusive : Boolean := True;
      --  Mutually exclusive (else reentrant).
   end record;
   --  A callback group (the full view of RCL.Nodes.Callback_Group).

   type Subscription is limited record
      Reader  : RCL.DDS.Reader;
      Topic   : Name_Access;
      --  Fully qualified ROS name.
      Handle  : Handler_Access;
      --  Owned by the subscription.
      Group   : Group_Data;
   end record;
   type Subscription_Access is access all Subscription;

   type Timer_Entry is record
      State    : RCL.Timer_States.State_Access;
      Callback : RCL.Timers.Callback;
      Group    : Group_Data;
   end record;

   Max_Subscriptions : constant := 256;
   Max_Timers        : constant := 64;

   type Subscription_Array is array (1 .. Max_Subscriptions) of Subscription_Access;
   type Timer_Array is array (1 .. Max_Timers) of Timer_Entry;

   protected type Registry is
      procedure Add (S : Subscription_Access);
      procedure Add (T : Timer_Entry);
      --  ROS_Exception beyond Max_Subscriptions / Max_Timers.
      function Version return Natural;
      function Sub_Count return Natural;
      function Sub (I : Positive) return Subscription_Access;
      function Tim_Count return Natural;
      function Tim (I : Positive) return Timer_Entry;
      procedure Take_All (Subs : out Subscription_Array; N_Subs : out Natural;
                          Tims : out Timer_Array; N_Tims : out Natural);
      --  Empties the registry (finalization).
   private
      Ver    : Natural := 0;
      Subs   : Subscription_Array := [others => null];
      N_Sub  : Natural := 0;
      Tims   : Timer_Array := [others => (null, null, (others => <>))];
      N_Tim  : Natural := 0;
   end Registry;

   type Node_Core is abstract new Ada.Finalization.Limited_Controlled with record
      Entities  : Registry;
      Graph_Id  : RCL.Graph.Node_Id := RCL.Graph.No_Node;
      Params_On : Boolean := False;
      --  RCL.Parameters.Serve was done for the node.
      Current   : Group_Data;
      --  The group of the entities made from now on.
   end record;

   function Graph_Id (Node : RCL.Nodes.Node'Class) return RCL.Graph.Node_Id;
   --  The node as the graph announcements know it (its endpoints are
   --  announced under it).

   function Version (Node : RCL.Nodes.Node'Class) return Natural;
   --  Changes whenever a subscription or timer is added.
   function Subscription_Count (Node : RCL.Nodes.Node'Class) return Natural;
   function Get_Subscription
     (Node : RCL.Nodes.Node'Class; Index : Positive) return Subscription_Access;
   function Find_Subscription
     (Node : RCL.Nodes.Node'Class; Topic : String) return Subscription_Access;
   --  Node's first subscription on Topic (fully qualified); null if none.
   function Timer_Count (Node : RCL.Nodes.Node'Class) return Natural;
   function Get_Timer (Node : RCL.Nodes.Node'Class; Index : Positive) return Timer_Entry;
   function Next_Timer_Due (Node : RCL.Nodes.Node'Class) return Ada.Real_Time.Time;
   --  Time_Last when there is no active timer.

   function Serves_Parameters (Node : RCL.Nodes.Node'Class) return Boolean;
   procedure Set_Serves_Parameters (Node : in out RCL.Nodes.Node'Class);
   --  RCL.Parameters.Serve was done for Node.

   procedure Add_Endpoint
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      DDS_Topic : String;
      Name      : String;
      User_Data : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile;
      Added     : out Subscription_Access);
   --  A subscription of Node on DDS_Topic ("rq/addRequest", or rt/ and the
   --  topic) whose fully qualified ROS name is Name and whose reader
   --  carries User_Data (then the type hash) in its USER_DATA; Handle gets
   --  its samples and is owned by it once added (not when this raises).
   --  In Node's current callback group; announced in the graph.

   procedure Subscribe
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile);
   --  Add_Endpoint for a ROS topic: Topic expanded and remapped as by
   --  Node.Expand, on its DDS topic (rt/ and the name), no user data; Handle
   --  owned as there. The subscription is Node's: its registry keeps it and
   --  Node's finalization frees it (a subscription lives as long as its
   --  node; there is no unsubscribing), so the caller gets nothing to keep.
   --  What RCL.Nodes.Subscribe_Handler does.

   function Subscribe
     (Node      : in out RCL.Nodes.Node'Class;
      Type_Name : String;
      Topic     : String;
      Handle    : not null Handler_Access;
      QoS       : RCL.QoS.Profile) return Subscription_Access;
   --  The same, returning the subscription (still Node's) for callers that
   --  look at it again (an action client's matched publishers).

   function To_Info (Info : RCL.DDS.Sample_Info) return ROSIDL.Message_Info;
   --  What a callback is told of a sample (received now).

end RCL.Node_Entities;
