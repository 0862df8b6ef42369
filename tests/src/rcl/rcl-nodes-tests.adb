with Ada.Exceptions;
with Ada.Task_Identification;
with Ada.Streams;
with Ada.Strings.Fixed;
with AUnit.Assertions; use AUnit.Assertions;
with RCL.Contexts;
with RCL.Executors.Concurrent;
with RCL.Executors.Sequential;
with RCL.Names;
with RCL.Process_Context;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Suite_Support; use Suite_Support;
with System;

package body RCL.Nodes.Tests is

   use Ada.Streams;
   use type ROSIDL.GID;
   use type ROSIDL.Int64;
   use type RCL.DDS.Domain_Id;

   Type_Name : constant String := "test_msgs::msg::dds_::Bytes_";
   --  Any name: the raw layer does not interpret the bytes.

   function Payload (N : Natural) return Stream_Element_Array is
     ([1 => 0, 2 => 1, 3 => 0, 4 => 0, 5 => Stream_Element (N mod 256), 6 => 16#AB#,
       7 => 0, 8 => 0]);

   Spinner_Task : Ada.Task_Identification.Task_Id;
   Wrong_Task   : Boolean := False;
   --  Sequential executor: callbacks run in the spinning task (never on a
   --  DDS thread).

   --  Received samples, by callbacks.
   Count        : Natural := 0 with Atomic;
   Last_Data    : Stream_Element_Array (1 .. 8) := [others => 0];
   Last_Info    : ROSIDL.Message_Info;
   Raise_Next   : Boolean := False;

   procedure On_Data
     (Node : in out Nodes.Node'Class; Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node);
   begin
      if Raise_Next then
         Raise_Next := False;
         raise Constraint_Error with "raised on purpose by a test callback";
      end if;
      declare
         use type Ada.Task_Identification.Task_Id;
      begin
         Wrong_Task := Wrong_Task
           or else Ada.Task_Identification.Current_Task /= Spinner_Task;
      end;
      if Data'Length = Last_Data'Length then
         Last_Data := Data;
      end if;
      Last_Info := Info;
      Count := Count + 1;
   end On_Data;

   procedure Spin_Until (N : in out Node; Target : Natural; Pub : RCL.Publishers.Publisher) is
   begin
      --  Publishes until the callbacks counted Target samples (bounded).
      for I in 1 .. 100 loop
         exit when Count >= Target;
         Pub.Publish_Raw (Payload (I));
         N.Spin (During => 0.1);
      end loop;
   end Spin_Until;

   procedure Loopback (Unused : in out Fixture) is
      N   : Node := Init ("loopback_test", Namespace => "tests");
      Pub : constant RCL.Publishers.Publisher :=
        N.Publish_Raw (Type_Name, "~/raw");
   begin
      Assert (Pub.Topic = "/tests/loopback_test/raw", "expanded: " & Pub.Topic);
      N.Subscribe_Raw (Type_Name, "/tests/loopback_test/raw", On_Data'Access);
      Count := 0;
      Spinner_Task := Ada.Task_Identification.Current_Task;
      Wrong_Task := False;
      Spin_Until (N, 1, Pub);
      Assert (not Wrong_Task, "the callback ran in the spinning task");
      Assert (Count >= 1, "a sample arrived");
      Assert (Last_Data (1 .. 4) = [0, 1, 0, 0] and then Last_Data (6) = 16#AB#,
              "bytes unchanged");
      Assert (Last_Info.Publisher_GID = ROSIDL.GID (Pub.GID), "publisher gid in the info");
      Assert (Last_Info.Source_Timestamp > 0
              and then Last_Info.Source_Timestamp <= Last_Info.Received_Timestamp,
              "source timestamp set, before reception");
   end Loopback;

   procedure Callback_Exception (Unused : in out Fixture) is
      N   : Node := Init ("exception_test");
      Pub : constant RCL.Publishers.Publisher := N.Publish_Raw (Type_Name, "exc");
   begin
      N.Subscribe_Raw (Type_Name, "exc", On_Data'Access);
      Count := 0;
      Raise_Next := True;
      Spin_Until (N, 2, Pub);
      Assert (not Raise_Next, "the raising callback ran");
      Assert (Count >= 2, "later samples still delivered after a callback raised");
   end Callback_Exception;

   procedure Two_Nodes (Unused : in out Fixture) is
      A   : Node := Init ("node_a");
      B   : Node := Init ("node_b");
      Pub : constant RCL.Publishers.Publisher := A.Publish_Raw (Type_Name, "/between");
      E   : RCL.Executors.Sequential.Executor;
   begin
      B.Subscribe_Raw (Type_Name, "/between", On_Data'Access);
      E.Add (A);
      E.Add (B);
      Count := 0;
      for I in 1 .. 100 loop
         exit when Count >= 3;
         Pub.Publish_Raw (Payload (I));
         E.Spin (During => 0.1);
      end loop;
      Assert (Count >= 3, "node B receives node A's samples through one executor");
   end Two_Nodes;

   procedure QoS_Mismatch (Unused : in out Fixture) is
      N       : Node := Init ("qos_test");
      Pub     : constant RCL.Publishers.Publisher :=
        N.Publish_Raw (Type_Name, "mismatch", RCL.QoS.Sensor_Data);
      Control : Natural := 0;
      procedure On_Control
        (Node : in out Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Data, Info);
      begin
         Control := Control + 1;
      end On_Control;
   begin
      N.Subscribe_Raw (Type_Name, "mismatch", On_Data'Access, RCL.QoS.Default);
      N.Subscribe_Raw (Type_Name, "mismatch", On_Control'Access, RCL.QoS.Sensor_Data);
      Count := 0;
      for I in 1 .. 100 loop
         exit when Control >= 5;
         Pub.Publish_Raw (Payload (I));
         N.Spin (During => 0.05);
      end loop;
      Assert (Control >= 5, "a best-effort reader receives (control)");
      Assert (Count = 0, "a reliable reader gets nothing from a best-effort writer");
   end QoS_Mismatch;

   procedure Await_Liveliness_Change
     (Watcher : in out Node;
      Topic   : String;
      Writer  : out ROSIDL.GID;
      Alive   : out Boolean;
      Found   : out Boolean) is
   begin
      for I in 1 .. 100 loop
         Watcher.Take_Liveliness_Change (Topic, Writer, Alive, Found);
         exit when Found;
         delay 0.05;
      end loop;
   end Await_Liveliness_Change;
   --  The next liveliness change of a writer of Topic, waiting up to 5 s;
   --  Found is False when none came.

   procedure Publisher_Liveliness (Unused : in out Fixture) is
      Leased   : constant RCL.QoS.Profile := (RCL.QoS.Default with delta Lease => 0.5);
      Watcher  : Node := Init ("liveliness_watcher");
      Writer   : ROSIDL.GID := [others => 0];
      G        : ROSIDL.GID;
      Alive, Found : Boolean;
      Came_Alive, Lost : Boolean := False;
      Raised   : Boolean := False;
   begin
      Watcher.Subscribe_Raw (Type_Name, "/leased", On_Data'Access, Leased);
      Watcher.Track_Liveliness ("/leased");
      Watcher.Track_Liveliness ("leased");   --  twice: no effect
      declare
         Other : Node := Init ("liveliness_publisher");
         Pub   : constant RCL.Publishers.Publisher :=
           Other.Publish_Raw (Type_Name, "/leased", Leased);
      begin
         Writer := ROSIDL.GID (Pub.GID);
         Pub.Publish_Raw (Payload (1));
         Await_Liveliness_Change (Watcher, "/leased", G, Alive, Found);
         Came_Alive := Found and then Alive and then G = Writer;
      end;
      --  The publisher is gone: reported lost.
      Await_Liveliness_Change (Watcher, "/leased", G, Alive, Found);
      Lost := Found and then not Alive and then G = Writer;
      Assert (Came_Alive, "the publisher is reported alive, with its GID");
      Assert (Lost, "the deleted publisher is reported lost, with its GID");
      begin
         Watcher.Track_Liveliness ("/not_subscribed");
      exception
         when E : ROS_Exception =>
            Raised := Ada.Strings.Fixed.Index
              (Ada.Exceptions.Exception_Message (E), "/not_subscribed") > 0;
      end;
      Assert (Raised, "no subscription on the topic: ROS_Exception naming it");
   end Publisher_Liveliness;

   --  Tracking started after the publisher was matched (and had become
   --  alive unseen): the publisher is reported alive at once, and lost when
   --  it goes. Before the tracker discarded the changes accumulated ahead of
   --  its listener, nothing was reported here (the deletion summed with the
   --  unseen "alive" to no change) and a team saw a killed robot only when
   --  DDS deleted its writer 10 s later.
   procedure Liveliness_Tracked_Late (Unused : in out Fixture) is
      Leased   : constant RCL.QoS.Profile := (RCL.QoS.Default with delta Lease => 0.5);
      Watcher  : Node := Init ("late_liveliness_watcher");
      Writer   : ROSIDL.GID := [others => 0];
      G        : ROSIDL.GID;
      Alive, Found : Boolean;
      Came_Alive, Lost : Boolean := False;
   begin
      Watcher.Subscribe_Raw (Type_Name, "/leased_late", On_Data'Access, Leased);
      declare
         Other : Node := Init ("late_liveliness_publisher");
         Pub   : constant RCL.Publishers.Publisher :=
           Other.Publish_Raw (Type_Name, "/leased_late", Leased);
      begin
         Writer := ROSIDL.GID (Pub.GID);
         Count := 0;
         for I in 1 .. 100 loop
            Pub.Publish_Raw (Payload (I));
            Watcher.Spin (During => 0.05);
            exit when Count > 0;
         end loop;
         Assert (Count > 0, "the watcher receives the publisher (matched, alive)");
         Watcher.Track_Liveliness ("/leased_late");
         Watcher.Take_Liveliness_Change ("/leased_late", G, Alive, Found);
         Came_Alive := Found and then Alive and then G = Writer;
      end;
      Await_Liveliness_Change (Watcher, "/leased_late", G, Alive, Found);
      Lost := Found and then not Alive and then G = Writer;
      Assert (Came_Alive, "a publisher matched before the tracking is reported alive at once");
      Assert (Lost, "and reported lost when it goes, with its GID");
   end Liveliness_Tracked_Late;

   Ticks : Natural := 0 with Atomic;

   procedure Tick (Node : in out Nodes.Node'Class; Timer : in out RCL.Timers.Timer;
                   Elapsed : Duration)
   is
      pragma Unreferenced (Node, Elapsed);
   begin
      Ticks := Ticks + 1;
      if Ticks = 3 then
         Timer.Cancel;
      end if;
   end Tick;

   procedure Timer_Spin (Unused : in out Fixture) is
      N : Node := Init ("timer_test");
      T : RCL.Timers.Timer;
   begin
      Ticks := 0;
      T := N.Timer_Add (0.01, Tick'Access);
      for I in 1 .. 200 loop
         N.Spin (Once => True, During => 1.0);
         exit when T.Is_Canceled;
      end loop;
      Assert (Ticks = 3, "three ticks then canceled by the callback:" & Ticks'Image);
      N.Spin (During => 0.05);
      Assert (Ticks = 3, "no tick once canceled");
   end Timer_Spin;

   procedure Concurrent (Unused : in out Fixture) is
      N   : Node := Init ("concurrent_test");
      Pub : constant RCL.Publishers.Publisher := N.Publish_Raw (Type_Name, "conc");
      E   : RCL.Executors.Concurrent.Tuned_Executor
        (Max_Nodes => 1, Queue_Size => 4, Threads => 3, Priority => System.Default_Priority);
      Seen : Natural := 0;
      Me   : constant Ada.Task_Identification.Task_Id := Ada.Task_Identification.Current_Task;
      protected Counter is
         procedure Add (In_Pool : Boolean);
         function Value return Natural;
         function All_In_Pool return Boolean;
      private
         V    : Natural := 0;
         Pool : Boolean := True;
      end Counter;
      protected body Counter is
         procedure Add (In_Pool : Boolean) is
         begin
            V := V + 1;
            Pool := Pool and then In_Pool;
         end Add;
         function Value return Natural is (V);
         function All_In_Pool return Boolean is (Pool);
      end Counter;
      procedure On_Conc
        (Node : in out Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Data, Info);
         use type Ada.Task_Identification.Task_Id;
      begin
         Counter.Add (In_Pool => Ada.Task_Identification.Current_Task /= Me);
      end On_Conc;
   begin
      N.Subscribe_Raw (Type_Name, "conc", On_Conc'Access);
      E.Add (N);
      for I in 1 .. 100 loop
         exit when Counter.Value >= 10;
         Pub.Publish_Raw (Payload (I));
         E.Spin (During => 0.05);
      end loop;
      Seen := Counter.Value;
      Assert (Seen >= 10, "the task pool ran the callbacks:" & Seen'Image);
      Assert (Counter.All_In_Pool, "callbacks ran on pool tasks, not the spinning task");
      E.Shutdown;
      Assert (E.Is_Shut_Down, "shut down deterministically");
   end Concurrent;

   procedure Callback_Groups (Unused : in out Fixture) is
      --  Three pool tasks, two timers and one subscription whose callbacks
      --  each take 30 ms: in the node's default (mutually exclusive) group
      --  they never overlap; in a reentrant group they do.
      protected Overlap is
         procedure Enter;
         procedure Leave;
         procedure Reset;
         function Most return Natural;
      private
         Now, Max : Natural := 0;
      end Overlap;
      protected body Overlap is
         procedure Enter is
         begin
            Now := Now + 1;
            Max := Natural'Max (Max, Now);
         end Enter;
         procedure Leave is
         begin
            Now := Now - 1;
         end Leave;
         procedure Reset is
         begin
            Now := 0;
            Max := 0;
         end Reset;
         function Most return Natural is (Max);
      end Overlap;
      Runs : Natural := 0 with Atomic;

      procedure Busy is
      begin
         Overlap.Enter;
         delay 0.03;
         Overlap.Leave;
         Runs := Runs + 1;
      end Busy;

      procedure On_Tick
        (Node : in out RCL.Nodes.Node'Class; Timer : in out RCL.Timers.Timer;
         Elapsed : Duration)
      is
         pragma Unreferenced (Node, Timer, Elapsed);
      begin
         Busy;
      end On_Tick;

      procedure On_Sample
        (Node : in out Nodes.Node'Class; Data : RCL.DDS.Byte_Array; Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Data, Info);
      begin
         Busy;
      end On_Sample;

      function Most_Overlap (Kind : Callback_Group_Kind; Topic : String) return Natural is
         N   : Node := Init ("groups_test_" & Topic);
         Pub : constant RCL.Publishers.Publisher := N.Publish_Raw (Type_Name, Topic);
         E   : RCL.Executors.Concurrent.Tuned_Executor
           (Max_Nodes => 1, Queue_Size => 16, Threads => 3,
            Priority => System.Default_Priority);
      begin
         if Kind = Reentrant then
            N.Set_Callback_Group (N.Create_Callback_Group (Reentrant));
         end if;
         Assert (Nodes.Kind (N.Current_Callback_Group) = Kind, "current group set");
         N.Timer_Add (0.01, On_Tick'Access);
         N.Timer_Add (0.01, On_Tick'Access);
         N.Subscribe_Raw (Type_Name, Topic, On_Sample'Access);
         Overlap.Reset;
         Runs := 0;
         E.Add (N);
         for I in 1 .. 100 loop
            exit when Runs >= 30;
            Pub.Publish_Raw (Payload (I));
            E.Spin (During => 0.02);
         end loop;
         E.Shutdown;
         Assert (Runs >= 30, "callbacks ran:" & Runs'Image);
         return Overlap.Most;
      end Most_Overlap;

      Exclusive_Most : constant Natural := Most_Overlap (Mutually_Exclusive, "groups_excl");
      Reentrant_Most : constant Natural := Most_Overlap (Reentrant, "groups_reent");
   begin
      Assert (Exclusive_Most = 1, "default group: one callback at a time, saw"
              & Exclusive_Most'Image);
      Assert (Reentrant_Most >= 2, "reentrant group: callbacks in parallel, saw at most"
              & Reentrant_Most'Image);
      declare
         A : Node := Init ("groups_owner_a");
         B : constant Node := Init ("groups_owner_b");
         G : constant Callback_Group := A.Create_Callback_Group (Reentrant);
      begin
         Assert (Belongs_To (G, A) and not Belongs_To (G, B), "a group belongs to its node");
         Assert (Belongs_To (B.Default_Callback_Group, B), "the default group");
         Assert (Id (A.Create_Callback_Group (Mutually_Exclusive)) = Id (G) + 1,
                 "groups numbered in order");
      end;
   end Callback_Groups;

   Typed_Count : Natural := 0;
   Typed_Text  : access String;

   procedure On_String
     (Node : in out Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Typed_Count := Typed_Count + 1;
      Typed_Text := new String'(Msg ("data").Get_String);
   end On_String;

   procedure Malformed_Bytes (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "String");
      N   : Node := Init ("malformed_test");
      Pub : RCL.Publishers.Publisher := N.Publish (Support, "malformed");
      Msg : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
      Bad : constant Stream_Element_Array :=
        [0, 1, 0, 0, 16#E8#, 16#03#, 0, 0, Character'Pos ('h'), 0, 0, 0];
      --  A string of length 1000 in 4 bytes: must be rejected, not over-read.
   begin
      N.Subscribe (Support, "malformed", On_String'Access);
      Msg ("data").Set_String ("valid");
      Typed_Count := 0;
      for I in 1 .. 100 loop
         exit when Typed_Count > 0;
         Pub.Publish_Raw (Bad);
         Pub.Publish (Msg);
         N.Spin (During => 0.05);
      end loop;
      Assert (Typed_Count > 0 and then Typed_Text.all = "valid",
              "malformed samples are skipped (logged), valid ones delivered");
   end Malformed_Bytes;

   Big_Length : Natural := 0 with Atomic;

   procedure On_Big
     (Node : in out Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Big_Length := Msg ("data").As_Array.Length;
   end On_Big;

   procedure Big_Message (Unused : in out Fixture) is
      Support : constant ROSIDL.Typesupport.Message_Support :=
        ROSIDL.Typesupport.Get_Message_Support ("std_msgs", "UInt8MultiArray");
      Size    : constant := 3_000_000;
      N       : Node := Init ("big_message_test");
      Pub     : RCL.Publishers.Publisher :=
        N.Publish (Support, "big", (RCL.QoS.Default with delta Depth => 2));
      Msg     : constant ROSIDL.Dynamic.Message := ROSIDL.Dynamic.Init (Support);
      Failed  : Boolean := False with Atomic;

      task Small_Stack with Storage_Size => 256 * 1024;
      --  Publishes a 3 MB message: must not need a stack buffer of that size.
      task body Small_Stack is
      begin
         Pub.Publish (Msg);
      exception
         when others =>
            Failed := True;
      end Small_Stack;
   begin
      Msg ("data").As_Array.Resize (Size);
      N.Subscribe (Support, "big", On_Big'Access);
      Big_Length := 0;
      for I in 1 .. 200 loop
         exit when Pub.Matched_Subscriptions > 0;
         delay 0.01;
      end loop;
      --  The task starts at the "begin" above: publish again from here if
      --  it ran before the subscription matched.
      for I in 1 .. 100 loop
         exit when Big_Length > 0 or else Failed;
         if I mod 20 = 0 then
            Pub.Publish (Msg);
         end if;
         N.Spin (During => 0.05);
      end loop;
      Assert (not Failed, "publishing 3 MB from a task with a 256 KiB stack");
      Assert (Big_Length = Size, "3 MB received:" & Big_Length'Image);
   end Big_Message;

   procedure Errors (Unused : in out Fixture) is
      N : constant Node := Init ("error_test");
      pragma Unreferenced (N);
      function Message_Of_Bad_Name return String is
      begin
         declare
            Ignored : constant Node := Init ("bad-name");
         begin
            return "";
         end;
      exception
         when E : RCL.Names.Name_Error =>
            return Ada.Exceptions.Exception_Message (E);
      end Message_Of_Bad_Name;
      function Message_Of_Bad_Type return String is
      begin
         declare
            W : RCL.DDS.Writer;
         begin
            RCL.DDS.Create (W, RCL.Process_Context.Participant.all, "bad topic name!", Type_Name,
                            RCL.QoS.Default);
            return "";
         end;
      exception
         when E : ROS_Exception =>
            return Ada.Exceptions.Exception_Message (E);
      end Message_Of_Bad_Type;
      Bad_Type : constant String := Message_Of_Bad_Type;
   begin
      Assert (Contains (Message_Of_Bad_Name, "'-'"),
              "invalid node name names the character");
      Assert (Contains (Bad_Type, "creating topic ""bad topic name!""")
              and then Contains (Bad_Type, "Bad Parameter"),
              "a DDS error becomes ROS_Exception saying what was attempted: " & Bad_Type);
      Assert (RCL.Contexts.Parse_Domain_Id ("7") = 7, "domain id");
      declare
         Raised : Boolean := False;
      begin
         begin
            Assert (RCL.Contexts.Parse_Domain_Id ("300") = 0, "unreachable");
         exception
            when E : ROS_Exception =>
               Raised := Ada.Strings.Fixed.Index
                 (Ada.Exceptions.Exception_Message (E), "ROS_DOMAIN_ID") > 0;
         end;
         Assert (Raised, "bad ROS_DOMAIN_ID named");
      end;
   end Errors;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite :=
        new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("nodes: raw loopback with info", Loopback'Access));
      Result.Add_Test (Caller.Create ("nodes: callback exception", Callback_Exception'Access));
      Result.Add_Test (Caller.Create ("nodes: two nodes, one executor", Two_Nodes'Access));
      Result.Add_Test (Caller.Create ("nodes: QoS mismatch", QoS_Mismatch'Access));
      Result.Add_Test (Caller.Create ("nodes: publisher liveliness (alive, lost)",
                                      Publisher_Liveliness'Access));
      Result.Add_Test (Caller.Create ("nodes: liveliness tracked after matching",
                                      Liveliness_Tracked_Late'Access));
      Result.Add_Test (Caller.Create ("nodes: timers", Timer_Spin'Access));
      Result.Add_Test (Caller.Create ("nodes: concurrent executor", Concurrent'Access));
      Result.Add_Test (Caller.Create ("nodes: callback groups in the concurrent executor",
                                      Callback_Groups'Access));
      Result.Add_Test (Caller.Create ("nodes: errors", Errors'Access));
      Result.Add_Test (Caller.Create ("nodes: malformed bytes", Malformed_Bytes'Access));
      Result.Add_Test (Caller.Create ("nodes: 3 MB message", Big_Message'Access));
      return Result;
   end Suite;

end RCL.Nodes.Tests;
