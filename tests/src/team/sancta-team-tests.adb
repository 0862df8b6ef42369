with Ada.Containers;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;  use Ada.Strings.Unbounded;
with Ada.Text_IO;
with AUnit.Assertions;        use AUnit.Assertions;
with Sancta.Geometry;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Values;
with Sancta.Team.Agents;
with Sancta.Team.Replicated_Databases;
with Sancta.Commands.Team_Demos;
with Sancta.Team.Goal_Trackers;
with Sancta.Team.Goal_Trackers.Contract_Tests;
with Sancta.Team.Grid_Costs;
with Sancta.Robot.Grids;
with Sancta.Team.Missions;
with Sancta.Team.Networks;
with Sancta.Team.Plans;
with Suite_Support; use Suite_Support;

package body Sancta.Team.Tests is

   use Sancta.Team.Networks;
   use Sancta.Team.Replicated_Databases;
   use type Ada.Containers.Count_Type;
   use type Plans.Tour_Vectors.Vector;

   Lease : constant Duration := 0.5;
   subtype Real is Sancta.Geometry.Real;

   function Wait_Until
     (Condition : not null access function return Boolean;
      Limit     : Duration := 15.0) return Boolean
   is
      Waited : Duration := 0.0;
   begin
      while not Condition.all loop
         if Waited >= Limit then
            return False;
         end if;
         delay 0.05;
         Waited := Waited + 0.05;
      end loop;
      return True;
   end Wait_Until;

   type Node is record
      Net : Network_Access;
      Db  : Team_Database_Access;
   end record;

   function Make (Team, Id : String; Groups : String := "robots") return Node is
      N : Node;
   begin
      N.Net := Create (Id, Groups => Groups, Lease => Lease, Team => Team);
      N.Db := new Team_Database (N.Net);
      N.Db.Attach;
      return N;
   end Make;

   --  Network ---------------------------------------------------------------------

   type Recorder is new Consumer with record
      Log : Unbounded_String;
   end record;
   overriding procedure On_Message
     (This : in out Recorder; Sender, Channel, Payload : String);

   protected Record_Lock is
      procedure Add (To : in out Unbounded_String; Text : String);
   end Record_Lock;
   protected body Record_Lock is
      procedure Add (To : in out Unbounded_String; Text : String) is
      begin
         Append (To, Text);
      end Add;
   end Record_Lock;

   overriding procedure On_Message
     (This : in out Recorder; Sender, Channel, Payload : String) is
   begin
      Record_Lock.Add (This.Log, "[" & Sender & ":" & Channel & ":" & Payload & "]");
   end On_Message;

   procedure Test_Destinations (T : in out Fixture) is
      pragma Unreferenced (T);
      A  : constant Node := Make ("t_dest", "a");
      B  : constant Node := Make ("t_dest", "b");
      C  : constant Node := Make ("t_dest", "c", Groups => "operators");
      RA, RB, RC : aliased Recorder;
      RX : aliased Recorder;

      function All_Met return Boolean is
        (A.Net.Members.Length = 3 and then B.Net.Members.Length = 3
         and then C.Net.Members.Length = 3);
      function Delivered return Boolean is
        (Contains (To_String (RA.Log), "last")
         and then Contains (To_String (RB.Log), "last")
         and then Contains (To_String (RC.Log), "last"));
      function Has (R : Recorder; Text : String) return Boolean is
        (Contains (To_String (R.Log), Text));
   begin
      A.Net.Subscribe ("chat", RA'Unchecked_Access);
      B.Net.Subscribe ("chat", RB'Unchecked_Access);
      C.Net.Subscribe ("chat", RC'Unchecked_Access);
      A.Net.Subscribe ("other", RX'Unchecked_Access);
      A.Net.Start;
      B.Net.Start;
      C.Net.Start;
      Assert (Wait_Until (All_Met'Access), "the three nodes never saw each other");
      C.Net.Send (To_Group ("robots"), "chat", "to-robots");
      A.Net.Send (To_Node ("b"), "chat", "to-b");
      B.Net.Send (To_All, "chat", "to-all");
      B.Net.Send (To_All, "other", "elsewhere");
      delay 0.3;
      C.Net.Send (To_All, "chat", "last");
      Assert (Wait_Until (Delivered'Access), "messages not delivered");
      Assert (Has (RA, "[c:chat:to-robots]") and then Has (RB, "[c:chat:to-robots]"),
              "group message missing: " & To_String (RA.Log) & " / " & To_String (RB.Log));
      Assert (not Has (RC, "to-robots"), "group message reached a non-member");
      Assert (Has (RB, "[a:chat:to-b]") and then not Has (RA, "to-b")
              and then not Has (RC, "to-b"), "node message went astray");
      Assert (Has (RA, "to-all") and then Has (RB, "to-all") and then Has (RC, "to-all"),
              "broadcast missing");
      Assert (not Has (RA, "elsewhere") and then Has (RX, "[b:other:elsewhere]"),
              "channels mixed up: " & To_String (RA.Log));
      A.Net.Stop;
      B.Net.Stop;
      C.Net.Stop;
   end Test_Destinations;

   type Watcher is new Membership_Listener with record
      Lost, Joined : Unbounded_String;
   end record;
   overriding procedure On_Joined (This : in out Watcher; Member : String);
   overriding procedure On_Lost (This : in out Watcher; Member : String);
   overriding procedure On_Joined (This : in out Watcher; Member : String) is
   begin
      Record_Lock.Add (This.Joined, Member & ";");
   end On_Joined;
   overriding procedure On_Lost (This : in out Watcher; Member : String) is
   begin
      Record_Lock.Add (This.Lost, Member & ";");
   end On_Lost;

   procedure Test_Presence (T : in out Fixture) is
      pragma Unreferenced (T);
      A : constant Node := Make ("t_pres", "a");
      B : constant Node := Make ("t_pres", "b");
      W : aliased Watcher;
      function Met return Boolean is (A.Net.Is_Member ("b"));
      function Gone return Boolean is (Contains (To_String (W.Lost), "b;"));
      function Joined return Boolean is
        (Contains (To_String (W.Joined), "b;"));
      --  (The listener hears of the join just after Is_Member turns True.)
   begin
      A.Net.Add_Membership_Listener (W'Unchecked_Access);
      A.Net.Start;
      B.Net.Start;
      Assert (Wait_Until (Met'Access), "a never saw b");
      Assert (Wait_Until (Joined'Access), "no join event");
      B.Net.Stop;
      Assert (Wait_Until (Gone'Access), "the loss of b was not reported");
      Assert (not A.Net.Is_Member ("b"), "b still a member after its lease");
      A.Net.Stop;
   end Test_Presence;

   --  Replicated database -------------------------------------------------------------

   type Counter is new Runtime.Local_Databases.Listener with record
      Calls : Natural := 0;
      Last  : Unbounded_String;
   end record;
   overriding procedure On_Key_Stored
     (This : in out Counter; Key : String; Value : Runtime.Values.Value'Class);
   overriding function Listener_Name (This : Counter) return String is ("counter");
   overriding procedure On_Key_Stored
     (This : in out Counter; Key : String; Value : Runtime.Values.Value'Class)
   is
      pragma Unreferenced (Key);
   begin
      This.Calls := This.Calls + 1;
      This.Last := To_Unbounded_String (Value.Image);
   end On_Key_Stored;

   procedure Test_Convergence (T : in out Fixture) is
      pragma Unreferenced (T);
      Nodes : constant array (1 .. 3) of Node :=
        [Make ("t_conv", "n1"), Make ("t_conv", "n2"), Make ("t_conv", "n3")];
      L : aliased Counter;

      function All_Met return Boolean is
        (for all N of Nodes => N.Net.Members.Length = 3);
      function Same return Boolean is
        (Nodes (1).Db.Digest = Nodes (2).Db.Digest
         and then Nodes (2).Db.Digest = Nodes (3).Db.Digest
         and then Nodes (1).Db.Keys.Length = 40);

      task type Writer (Me : Positive);
      task body Writer is
      begin
         for Round in 1 .. 10 loop
            for K in 1 .. 20 loop
               Nodes (Me).Db.Put ("shared/" & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left),
                                  "n" & Me'Image & " r" & Round'Image);
            end loop;
         end loop;
         for K in 1 .. 20 loop
            if (K - 1) mod 3 + 1 = Me then
               Nodes (Me).Db.Put ("own/" & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left),
                                  Runtime.Values.Integer_Value'(Data => Long_Long_Integer (K)));
            end if;
         end loop;
      exception
         when E : others =>
            Ada.Text_IO.Put_Line (Ada.Exceptions.Exception_Information (E));
      end Writer;
   begin
      Nodes (2).Db.Listen ("own/1", L'Unchecked_Access);
      for N of Nodes loop
         N.Net.Start;
      end loop;
      Assert (Wait_Until (All_Met'Access), "the nodes never met");
      declare
         W1 : Writer (1);
         W2 : Writer (2);
         W3 : Writer (3);
      begin
         null;
      end;
      Assert (Wait_Until (Same'Access), "replicas differ:" & ASCII.LF & Nodes (1).Db.Digest
              & "--" & ASCII.LF & Nodes (3).Db.Digest);
      for K in 1 .. 20 loop
         declare
            Key : constant String := "own/" & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left);
         begin
            for N of Nodes loop
               Assert (N.Db.Contains (Key)
                       and then N.Db.Get (Key).Image = K'Image (2 .. K'Image'Last),
                       Key & " lost or wrong on " & N.Net.Id);
            end loop;
         end;
      end loop;
      --  Every node wrote every shared key 10 times: the winner is the
      --  highest (revision, writer).
      for K in 1 .. 20 loop
         declare
            Key : constant String :=
              "shared/" & Ada.Strings.Fixed.Trim (K'Image, Ada.Strings.Left);
         begin
            Assert (Nodes (1).Db.Revision (Key) >= 10, Key & ": revision below 10");
         end;
      end loop;
      Assert (L.Calls >= 1 and then To_String (L.Last) = "1",
              "listener on own/1 called" & L.Calls'Image & " times, last " & To_String (L.Last));
      for N of Nodes loop
         N.Net.Stop;
      end loop;
   end Test_Convergence;

   procedure Test_Late_Joiner (T : in out Fixture) is
      pragma Unreferenced (T);
      A : constant Node := Make ("t_late", "a");
      B : constant Node := Make ("t_late", "b");
      C : Node;
      function Met return Boolean is (A.Net.Members.Length = 2);
      function Caught_Up return Boolean is (C.Db.Digest = A.Db.Digest);
   begin
      A.Net.Start;
      B.Net.Start;
      Assert (Wait_Until (Met'Access), "a and b never met");
      for K in 1 .. 30 loop
         A.Db.Put ("a/" & K'Image, "value" & K'Image);
         B.Db.Put ("b/" & K'Image, "value" & K'Image);
      end loop;
      A.Db.Put ("a/ 1", "rewritten");
      delay 0.5;
      C := Make ("t_late", "c");
      C.Net.Start;
      Assert (Wait_Until (Caught_Up'Access), "the late joiner did not get the state:"
              & C.Db.Keys.Length'Image & " keys");
      Assert (C.Db.Get_String ("a/ 1") = "rewritten", "late joiner has an old value");
      Assert (C.Db.Keys.Length = 60, "late joiner has" & C.Db.Keys.Length'Image & " keys");
      A.Net.Stop;
      B.Net.Stop;
      C.Net.Stop;
   end Test_Late_Joiner;

   procedure Test_Cut_And_Rejoin (T : in out Fixture) is
      pragma Unreferenced (T);
      A : constant Node := Make ("t_cut", "a");
      B : constant Node := Make ("t_cut", "b");
      C : constant Node := Make ("t_cut", "c");
      function All_Met return Boolean is
        (A.Net.Members.Length = 3 and then C.Net.Members.Length = 3);
      function Cut_Seen return Boolean is
        (not A.Net.Is_Member ("c") and then not C.Net.Is_Member ("a"));
      function Same return Boolean is
        (A.Db.Digest = C.Db.Digest and then B.Db.Digest = C.Db.Digest
         and then C.Db.Contains ("while/a") and then A.Db.Contains ("while/c"));
   begin
      A.Net.Start;
      B.Net.Start;
      C.Net.Start;
      Assert (Wait_Until (All_Met'Access), "never met");
      A.Db.Put ("before", "1");
      C.Net.Isolate (True);
      Assert (Wait_Until (Cut_Seen'Access), "the cut was not noticed");
      A.Db.Put ("while/a", "from a");
      B.Db.Put ("before", "2");
      C.Db.Put ("while/c", "from c");
      delay 0.3;
      Assert (not C.Db.Contains ("while/a"), "the cut node received data");
      C.Net.Isolate (False);
      Assert (Wait_Until (Same'Access), "no catch-up after rejoin:" & ASCII.LF & A.Db.Digest
              & "--" & ASCII.LF & C.Db.Digest);
      Assert (C.Db.Get_String ("before") = "2", "old value after rejoin");
      Assert (A.Db.Get_String ("while/c") = "from c", "the cut node's write was lost");
      A.Net.Stop;
      B.Net.Stop;
      C.Net.Stop;
   end Test_Cut_And_Rejoin;

   procedure Test_Republish_Rule (T : in out Fixture) is
      --  On a join a node republishes what it wrote, what the joiner wrote
      --  and what writers no longer members wrote; not the entries of the
      --  other members (they republish those themselves).
      pragma Unreferenced (T);
      A : constant Node := Make ("t_repub", "a");
      B : constant Node := Make ("t_repub", "b");
      function Met return Boolean is (A.Net.Is_Member ("b") and then B.Net.Is_Member ("a"));
      function Has_All return Boolean is (A.Db.Keys.Length = 15);
      function B_Gone return Boolean is (not A.Net.Is_Member ("b"));
      Before : Long_Long_Integer;
      --  Membership events a saw: a process starved longer than the lease
      --  loses b and takes it back, which changes what a republishes.
      W : aliased Watcher;
      function Events return String is (To_String (W.Lost) & "|" & To_String (W.Joined));
   begin
      A.Net.Add_Membership_Listener (W'Unchecked_Access);
      A.Net.Start;
      B.Net.Start;
      Assert (Wait_Until (Met'Access), "a and b never met");
      for K in 1 .. 10 loop
         A.Db.Put ("a/" & K'Image, "from a");
      end loop;
      for K in 1 .. 5 loop
         B.Db.Put ("b/" & K'Image, "from b");
      end loop;
      Assert (Wait_Until (Has_All'Access), "a holds" & A.Db.Keys.Length'Image & " keys, not 15");
      --  Counted only over a call during which b stayed a member (no
      --  membership event, b a member before and after); tried again when
      --  the lease ran out meanwhile (a starved process), up to 20 times.
      for Attempt in 1 .. 21 loop
         Assert (Attempt <= 20, "b lost or rejoined during each of 20 resynchronisations: "
                 & Events);
         Assert (Wait_Until (Met'Access), "a and b never met again");
         declare
            Seen : constant String := Events;
         begin
            Before := A.Db.Republished_Count;
            A.Db.Resynchronise;
            if Events = Seen and then A.Net.Is_Member ("b") then
               Assert (A.Db.Republished_Count - Before = 10,
                       "a republished"
                       & Long_Long_Integer'Image (A.Db.Republished_Count - Before)
                       & " entries with b a member; expected its own 10");
               exit;
            end if;
         end;
      end loop;
      Before := A.Db.Republished_Count;
      A.Db.Resynchronise (Joined => "b");
      Assert (A.Db.Republished_Count - Before = 15,
              "on b's join a republished"
              & Long_Long_Integer'Image (A.Db.Republished_Count - Before)
              & " entries; expected 15 (b may have restarted and lost its own)");
      B.Net.Stop;
      Assert (Wait_Until (B_Gone'Access), "b never lost");
      Before := A.Db.Republished_Count;
      A.Db.Resynchronise;
      Assert (A.Db.Republished_Count - Before = 15,
              "with b gone a republished"
              & Long_Long_Integer'Image (A.Db.Republished_Count - Before)
              & " entries; expected 15 (nobody else holds b's)");
      A.Net.Stop;
   end Test_Republish_Rule;

   --  Missions and plans ---------------------------------------------------------------

   procedure Test_Mission_Errors (T : in out Fixture) is
      pragma Unreferenced (T);
      File : constant String := "out/test-team-bad-mission.xml";
      F    : Ada.Text_IO.File_Type;
   begin
      Ada.Text_IO.Create (F, Ada.Text_IO.Out_File, File);
      Ada.Text_IO.Put_Line (F, "<mission>");
      Ada.Text_IO.Put_Line (F, "  <goto id=""t1"" x=""1"" y=""2""/>");
      Ada.Text_IO.Put_Line (F, "  <goto id=""t2"" x=""oops"" y=""2""/>");
      Ada.Text_IO.Put_Line (F, "</mission>");
      Ada.Text_IO.Close (F);
      begin
         declare
            M : constant Missions.Mission := Missions.Read (File);
            pragma Unreferenced (M);
         begin
            Assert (False, "a bad number was accepted");
         end;
      exception
         when E : Missions.Format_Error =>
            Assert (Contains (Ada.Exceptions.Exception_Message (E), File & ":3:"),
                    "error not positioned: " & Ada.Exceptions.Exception_Message (E));
      end;
      declare
         M : constant Missions.Mission := Missions.Read ("share/missions/office-team.xml");
         use Missions;
      begin
         Assert (M.Tasks.Length >= 20 and then M.Robots.Length >= 4, "demo mission too small");
         Assert ((for some T of M.Tasks => T.Kind = Explore_Segment)
                 and then (for some T of M.Tasks => T.Kind = Choose_Entry),
                 "demo mission lacks OR tasks");
         for T of M.Tasks loop
            Assert (Decode (To_String (T.Id), Encode (T)) = T, "encode/decode differ");
         end loop;
      end;
   end Test_Mission_Errors;

   procedure Test_Plans (T : in out Fixture) is
      pragma Unreferenced (T);
      M : constant Missions.Mission := Missions.Read ("share/missions/office-team.xml");
      S : Plans.Snapshot;
   begin
      S.Generation := 3;
      for R of M.Robots loop
         S.Robots.Append (Plans.Robot_Position'(R.Id, (R.Start.X, R.Start.Y)));
      end loop;
      S.Tasks := M.Tasks;
      declare
         G : constant Plans.Plan := Plans.Greedy (S, "g");
         A : constant Plans.Plan := Plans.Anneal (S, 7, 0.5, G, "a");
         D : constant Plans.Plan := Plans.Decode (Plans.Encode (A, S), S);
         N : Natural := 0;
      begin
         for Tour of A.Tours loop
            N := N + Natural (Tour.Length);
         end loop;
         Assert (N = Natural (M.Tasks.Length), "annealed plan has" & N'Image & " steps");
         Assert (A.Value <= G.Value + 1.0E-6, "annealing from greedy made it worse");
         Assert (D.Tours = A.Tours and then abs (D.Value - A.Value) < 1.0E-6,
                 "plan text does not round-trip");
      end;
      --  Legs costed by a function (the A* lengths of the demo's summary).
      declare
         One : Plans.Snapshot;
         P   : Plans.Plan;
         Seg : Missions.Mission_Task;
         Go  : Missions.Mission_Task;
         function Doubled (From, To : Sancta.Geometry.Point) return Long_Float is
           (2.0 * Long_Float (Sancta.Geometry.Distance (From, To)));
      begin
         One.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("r"), (0.0, 0.0)));
         Go.Id := To_Unbounded_String ("go");
         Go.Points.Append (Missions.Point'(3.0, 4.0));
         Seg.Id := To_Unbounded_String ("seg");
         Seg.Kind := Missions.Explore_Segment;
         Seg.Points.Append (Missions.Point'(3.0, 8.0));
         Seg.Points.Append (Missions.Point'(3.0, 10.0));
         One.Tasks.Append (Go);
         One.Tasks.Append (Seg);
         P.Tours.Append (Plans.Step_Vectors.Empty_Vector);
         P.Tours (1).Append (Plans.Step'(Go.Id, 1));
         P.Tours (1).Append (Plans.Step'(Seg.Id, 1));
         --  Straight: 5 to go, 4 to the segment, 2 inside it.
         Assert (abs (Plans.Total (One, P) - 11.0) < 1.0E-9,
                 "straight total" & Plans.Total (One, P)'Image);
         --  Legs doubled, the inside of the segment not.
         Assert (abs (Plans.Total (One, P, Doubled'Access) - 20.0) < 1.0E-9,
                 "total with doubled legs" & Plans.Total (One, P, Doubled'Access)'Image);
         Assert (abs (Plans.Makespan (One, P, Doubled'Access) - 20.0) < 1.0E-9,
                 "makespan with doubled legs");
      end;
   end Test_Plans;

   --  A re-plan's start: the previous plan carried over to the new round.
   procedure Test_Carried_Over (T : in out Fixture) is
      pragma Unreferenced (T);
      function Point_Task (Id : String; X, Y : Sancta.Geometry.Real) return Missions.Mission_Task is
         Result : Missions.Mission_Task;
      begin
         Result.Id := To_Unbounded_String (Id);
         Result.Points.Append (Missions.Point'(X, Y));
         return Result;
      end Point_Task;
      function Ids (Tour : Plans.Step_Vectors.Vector) return String is
         Text : Unbounded_String;
      begin
         for St of Tour loop
            Append (Text, St.Task_Id & " ");
         end loop;
         return To_String (Text);
      end Ids;
      Old, Now : Plans.Snapshot;
      Adopted  : Plans.Plan;
      Dummy    : Long_Float;
   begin
      --  Round 1: a at x=0 does t1 t2, b at x=10 does t3 t4, c at x=20 does t5 t6.
      Old.Generation := 1;
      Old.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("a"), (0.0, 0.0)));
      Old.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("b"), (10.0, 0.0)));
      Old.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("c"), (20.0, 0.0)));
      for I in 1 .. 6 loop
         Old.Tasks.Append (Point_Task ("t" & Character'Val (Character'Pos ('0') + I),
                                       Sancta.Geometry.Real (((I - 1) / 2) * 10),
                                       Sancta.Geometry.Real (I)));
      end loop;
      Adopted.Generation := 1;
      for R in 1 .. 3 loop
         Adopted.Tours.Append (Plans.Step_Vectors.Empty_Vector);
         Adopted.Tours (R).Append (Plans.Step'(Old.Tasks (2 * R - 1).Id, 1));
         Adopted.Tours (R).Append (Plans.Step'(Old.Tasks (2 * R).Id, 1));
      end loop;
      Dummy := Plans.Evaluate (Old, Adopted);
      --  Round 2: b lost; t1 done; c now listed before a.
      Now.Generation := 2;
      Now.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("c"), (20.0, 5.0)));
      Now.Robots.Append (Plans.Robot_Position'(To_Unbounded_String ("a"), (0.0, 1.0)));
      for I in 2 .. 6 loop
         Now.Tasks.Append (Old.Tasks (I));
      end loop;
      declare
         C : constant Plans.Plan := Plans.Carried_Over (Old, Adopted, Now, "a");
         N : Natural := 0;
      begin
         Assert (C.Generation = 2 and then Natural (C.Tours.Length) = 2, "one tour per robot");
         for Tour of C.Tours loop
            N := N + Natural (Tour.Length);
         end loop;
         Assert (N = 5, "every task of the round once:" & N'Image);
         --  The survivors keep their remaining tasks in order, first.
         Assert (Ids (C.Tours (1)) (1 .. 6) = "t5 t6 ", "c keeps t5 t6: " & Ids (C.Tours (1)));
         Assert (Ids (C.Tours (2)) (1 .. 3) = "t2 ", "a keeps t2: " & Ids (C.Tours (2)));
         --  b's tasks (x = 10) go where the tour they join costs least.
         Assert (Ids (C.Tours (1)) & Ids (C.Tours (2)) /= "t5 t6 t2 ",
                 "the lost robot's tasks placed");
         Assert (abs (C.Value - Plans.Evaluate (Now, C'Unrestricted_Access.all)) < 1.0E-9,
                 "value set");
         Assert (Plans.Anneal (Now, 3, 0.2, C, "a").Value <= C.Value + 1.0E-6,
                 "annealing from the carried-over plan keeps or improves it");
      end;
      --  Not the adopted plan of its round: no tours.
      Adopted.Generation := 5;
      Assert (Plans.Carried_Over (Old, Adopted, Now, "a").Tours.Is_Empty,
              "a plan of another round is not carried over");
   end Test_Carried_Over;

   --  A robot joining gets tasks; tasks done stay done ---------------------------------

   procedure Test_Join (T : in out Fixture) is
      pragma Unreferenced (T);
      use Agents;
      Team : constant Unbounded_String := To_Unbounded_String ("t_join");
      function Robot (Id : String; X : Real) return Agent_Access is
         A : constant Agent_Access :=
           Create ((Id => To_Unbounded_String (Id), Team => Team, Lease => Lease,
                    Verbose => False, others => <>));
      begin
         A.Set_Pose ((X, 0.0));
         return A;
      end Robot;
      M  : Missions.Mission;
      R1 : constant Agent_Access := Robot ("r1", 0.0);
      R2 : constant Agent_Access := Robot ("r2", 10.0);
      R3 : Agent_Access;
      Op : constant Agent_Access :=
        Create ((Id => To_Unbounded_String ("operator"), Team => Team, Is_Robot => False,
                 Lease => Lease, Verbose => False, others => <>));
      First_Task : Unbounded_String;
      function Planned return Boolean is
        (R1.Adopted.Generation > 0 and then R1.Adopted.Generation = R1.Round.Generation);
      function Joined return Boolean is
        (R3.Adopted.Generation > 0 and then R3.Adopted.Generation = R3.Round.Generation
         and then R3.Round.Robots.Length = 3);
      function New_Robot_Has_Tasks return Boolean is
         S : constant Plans.Snapshot := R3.Round;
         P : constant Plans.Plan := R3.Adopted;
      begin
         if P.Generation = 0 or else P.Generation /= S.Generation then
            return False;
         end if;
         for K in 1 .. Natural (S.Robots.Length) loop
            if To_String (S.Robots (K).Id) = "r3" and then K <= Natural (P.Tours.Length)
              and then not P.Tours (K).Is_Empty
            then
               return True;
            end if;
         end loop;
         return False;
      end New_Robot_Has_Tasks;
   begin
      for K in 1 .. 9 loop
         declare
            Task_Def : Missions.Mission_Task;
         begin
            Task_Def.Id := To_Unbounded_String ("j" & Ada.Strings.Fixed.Trim (K'Image,
                                                Ada.Strings.Left));
            Task_Def.Points.Append (Missions.Point'(Real (K * 2), 5.0));
            M.Tasks.Append (Task_Def);
         end;
      end loop;
      Op.Publish_Mission (M);
      Assert (Wait_Until (Planned'Access), "no plan for two robots");
      --  r1 does its first task.
      declare
         Found : Boolean;
         Goal  : Missions.Point;
         Done  : Boolean;
      begin
         R1.Current_Goal (Found, Goal, First_Task);
         Assert (Found, "r1 has nothing to do");
         R1.Arrived (To_String (First_Task), Done);
         Assert (Done, "arriving did not complete the task");
      end;
      R3 := Robot ("r3", 20.0);
      Assert (Wait_Until (Joined'Access), "no round with the new robot");
      --  The round's first plan is the previous one carried over (r3 has
      --  nothing yet); annealing gives r3 its share.
      Assert (Wait_Until (New_Robot_Has_Tasks'Access), "the new robot got no task");
      declare
         S : constant Plans.Snapshot := R3.Round;
         P : constant Plans.Plan := R3.Adopted;
         Count : Natural := 0;
      begin
         Assert ((for all X of S.Tasks => X.Id /= First_Task), "a task done was re-planned");
         Assert (Natural (S.Tasks.Length) = 8, "round has" & S.Tasks.Length'Image & " tasks");
         for K in 1 .. Natural (S.Robots.Length) loop
            if To_String (S.Robots (K).Id) = "r3" then
               Assert (not P.Tours (K).Is_Empty, "the new robot got no task");
            end if;
            Count := Count + Natural (P.Tours (K).Length);
         end loop;
         Assert (Count = 8, "the plan allocates" & Count'Image & " tasks");
      end;
      R1.Stop;
      R2.Stop;
      R3.Stop;
      Op.Stop;
   end Test_Join;

   procedure Test_Task_While_Annealing (T : in out Fixture) is
      --  A robot takes its task as soon as the team's plan names it, while
      --  its own annealing still runs: both robots anneal for 3 s; a third
      --  node (this test) proposes a greedy plan as soon as the round is
      --  out; r2 must find its goal in that plan before its own proposal
      --  exists (an order of events, not a time: the agent task used to
      --  anneal in its loop and saw no plan until its annealing ended).
      pragma Unreferenced (T);
      use Agents;
      Team : constant Unbounded_String := To_Unbounded_String ("t_first_go");
      function Robot (Id : String; X : Real) return Agent_Access is
         A : constant Agent_Access :=
           Create ((Id => To_Unbounded_String (Id), Team => Team, Lease => Lease,
                    Budget => 3.0, Rounds => 0, Verbose => False, others => <>));
      begin
         A.Set_Pose ((X, 0.0));
         return A;
      end Robot;
      M       : Missions.Mission;
      R1      : constant Agent_Access := Robot ("r1", 0.0);
      R2      : constant Agent_Access := Robot ("r2", 10.0);
      Op      : constant Agent_Access :=
        Create ((Id => To_Unbounded_String ("operator"), Team => Team, Is_Robot => False,
                 Lease => Lease, Verbose => False, others => <>));
      Planner : constant Node := Make ("t_first_go", "planner", Groups => "operators");
      Found   : Boolean := False;
      Goal    : Missions.Point;
      Task_Id : Unbounded_String;
      function Round_Out return Boolean is (R1.Round.Generation > 0);
      function R2_Has_Goal return Boolean is
      begin
         R2.Current_Goal (Found, Goal, Task_Id);
         return Found;
      end R2_Has_Goal;
   begin
      for K in 1 .. 6 loop
         declare
            Task_Def : Missions.Mission_Task;
            X        : constant Real := (if K <= 3 then Real (K) else Real (7 + K));
            --  Three tasks near each robot.
         begin
            Task_Def.Id := To_Unbounded_String ("f" & Ada.Strings.Fixed.Trim (K'Image,
                                                Ada.Strings.Left));
            Task_Def.Points.Append (Missions.Point'(X, 3.0));
            M.Tasks.Append (Task_Def);
         end;
      end loop;
      Op.Publish_Mission (M);
      Assert (Wait_Until (Round_Out'Access), "no round");
      declare
         S : constant Plans.Snapshot := R1.Round;
         P : constant Plans.Plan := Plans.Greedy (S, "planner");
      begin
         Assert (Natural (S.Robots.Length) = 2, "round of" & S.Robots.Length'Image & " robots");
         Assert ((for all Tour of P.Tours => not Tour.Is_Empty), "greedy left a robot idle");
         Planner.Db.Put ("proposal/planner", Plans.Encode (P, S));
      end;
      Assert (Wait_Until (R2_Has_Goal'Access), "r2 never took a task");
      Assert (not R2.Database.Contains ("proposal/r2"),
              "r2 took its task " & To_String (Task_Id) & " only after its own annealing");
      Assert (R2.Adopted.Proposer = "planner",
              "r2 follows the plan of " & To_String (R2.Adopted.Proposer));
      R1.Stop;
      R2.Stop;
      Op.Stop;
      Planner.Net.Stop;
   end Test_Task_While_Annealing;

   procedure Test_Legs_Before_Round (T : in out Fixture) is
      --  With A* leg costs, a robot agent costs the legs between the
      --  mission's tasks as soon as the mission is known, before any round
      --  (here none ever opens: the robot has no pose, so it is not alive).
      pragma Unreferenced (T);
      use Agents;
      use Sancta.Robot.Grids;
      Team  : constant Unbounded_String := To_Unbounded_String ("t_warm_legs");
      G     : Grid (99, 99);
      Costs : Grid_Costs.Cost_Access;
      M     : Missions.Mission;
      Pairs : constant Natural := 4 * 3;
      --  Four goto tasks in distinct cells: every ordered pair.
   begin
      G.Origin := (0.0, 0.0);
      G.Resolution := 0.05;
      Costs := Grid_Costs.Create (G, Robot_Radius => 0.2, Cell => 0.2);
      for K in 1 .. 4 loop
         declare
            Task_Def : Missions.Mission_Task;
         begin
            Task_Def.Id := To_Unbounded_String ("w" & Ada.Strings.Fixed.Trim (K'Image,
                                                Ada.Strings.Left));
            Task_Def.Points.Append (Missions.Point'(Real (K), 2.0));
            M.Tasks.Append (Task_Def);
         end;
      end loop;
      declare
         R1 : constant Agent_Access :=
           Create ((Id => To_Unbounded_String ("r1"), Team => Team, Lease => Lease,
                    Costs => Costs, Verbose => False, others => <>));
         Op : constant Agent_Access :=
           Create ((Id => To_Unbounded_String ("operator"), Team => Team, Is_Robot => False,
                    Lease => Lease, Verbose => False, others => <>));
         function Costed return Boolean is (Costs.Cached_Legs >= Pairs);
      begin
         Assert (Costs.Cached_Legs = 0, "legs cached before the mission");
         Op.Publish_Mission (M);
         Assert (Wait_Until (Costed'Access),
                 "legs cached:" & Costs.Cached_Legs'Image & ", expected" & Pairs'Image);
         Assert (R1.Round.Generation = 0, "a round opened");
         R1.Stop;
         Op.Stop;
      end;
   end Test_Legs_Before_Round;

   --  The team_member's goal rule (the stall of the configuration demo) ---------------

   procedure Test_Goal_Tracker (T : in out Fixture) is
      pragma Unreferenced (T);
      use Goal_Trackers;
      Tracker : Goal_Tracker;
      G       : constant Sancta.Geometry.Point := (7.0, 7.0);
      Here    : constant Sancta.Geometry.Point := (2.0, 10.0);

      procedure Expect (Found : Boolean; Task_Id : String; At_Point : Sancta.Geometry.Point;
                        Wanted : Action; Why : String) is
         Got : constant Action := Tracker.Decide (Found, G, Task_Id, At_Point, 0.35);
      begin
         Assert (Got = Wanted, Why & ": " & Got'Image & " instead of " & Wanted'Image);
      end Expect;
   begin
      Expect (False, "", Here, Go_Idle, "no plan at first");
      Assert (Tracker.Is_Idle, "not idle without a plan");
      Expect (False, "", Here, Nothing, "still no plan");
      Expect (True, "s2b", Here, New_Goal, "first goal");
      Expect (True, "s2b", Here, Nothing, "same goal again");
      --  A new round: no adopted plan for a moment, then the same task back.
      Expect (False, "", Here, Go_Idle, "new round without a plan");
      Expect (True, "s2b", Here, New_Goal, "the same goal after an idle spell");
      Assert (not Tracker.Is_Idle, "idle with a goal");
      Expect (True, "s2c", Here, New_Goal, "another task at the same point");
      Expect (True, "s2c", (7.1, 7.1), At_Goal, "within the tolerance");
      Expect (True, "s2c", (7.3, 7.3), Nothing, "0.42 m away: not there, goal already sent");
   end Test_Goal_Tracker;

   --  Allocation legs along A* on a coarsened grid -------------------------------------

   procedure Test_Grid_Costs (T : in out Fixture) is
      pragma Unreferenced (T);
      use Sancta.Robot.Grids;
      --  10 m x 10 m at 0.05 m, a wall along x = 5 from y = 0 to 8 (a gap
      --  from 8 to 10).
      G : Grid (199, 199);
   begin
      G.Origin := (0.0, 0.0);
      G.Resolution := 0.05;
      Draw (G, (A => (5.0, 0.0), B => (5.0, 8.0), Thickness => 0.1));
      declare
         C : constant Grid := Grid_Costs.Coarsen (G, 4);
      begin
         Assert (Width (C) = 50 and then Height (C) = 50, "coarse size");
         Assert (abs (Long_Float (C.Resolution) - 0.2) < 1.0E-9, "coarse resolution");
         Assert (Is_Occupied_At (C, (5.0, 4.0)), "the wall is lost");
         Assert (not Is_Occupied_At (C, (5.0, 9.0)), "the gap is closed");
         Assert (not Is_Occupied_At (C, (2.0, 2.0)), "free space became occupied");
      end;
      declare
         Costs : constant Grid_Costs.Cost_Access :=
           Grid_Costs.Create (G, Robot_Radius => 0.2, Cell => 0.2);
         Around : constant Long_Float := Costs.Leg ((3.0, 2.0), (7.0, 2.0));
         Open   : constant Long_Float := Costs.Leg ((1.0, 1.0), (1.0, 5.0));
      begin
         --  Through the gap: at least up to y = 8 and back, about 4 + 2 x 6.
         Assert (Around > 14.0 and then Around < 18.0, "leg around the wall:" & Around'Image);
         Assert (abs (Open - 4.0) < 0.5, "open leg:" & Open'Image);
      end;
   end Test_Grid_Costs;

   --  The report's time split ---------------------------------------------------------------

   procedure Test_Arrivals (T : in out Fixture) is
      --  A robot on the x axis at 1 m/s: still until 2 s (first plan at
      --  1 s), to goto g1 at (5, 0) (done at 7 s), on to segment s1 from
      --  (10, 0) (reached within 0.5 m at 11.5 s) to (15, 0) (done at
      --  17 s), still until 20 s.
      pragma Unreferenced (T);
      use type Geometry.Real;
      package TD renames Commands.Team_Demos;
      Result : TD.Demo_Result;
      Tasks  : Missions.Task_Vectors.Vector;
      Robot  : TD.Robot_Summary;

      function X_At (Time : Long_Float) return Long_Float is
        (if Time <= 2.0 then 0.0 elsif Time <= 17.0 then Time - 2.0 else 15.0);

      function Near (A, B : Long_Float) return Boolean is (abs (A - B) <= 0.11);
   begin
      Tasks.Append (Missions.Mission_Task'
                      (Id => To_Unbounded_String ("g1"), Kind => Missions.Goto_Pose,
                       Points => Missions.Point_Vectors.To_Vector ((5.0, 0.0), 1)));
      declare
         S : Missions.Mission_Task :=
           (Id => To_Unbounded_String ("s1"), Kind => Missions.Explore_Segment, others => <>);
      begin
         --  Listed from its exit end: the entry is found from where it finished.
         S.Points.Append (Geometry.Point'(15.0, 0.0));
         S.Points.Append (Geometry.Point'(10.0, 0.0));
         Tasks.Append (S);
      end;
      Robot.Id := To_Unbounded_String ("r1");
      for K in 0 .. 200 loop
         Robot.Track.Append
           (TD.Track_Sample'(Time  => Long_Float (K) * 0.1,
                             Where => (Geometry.Real (X_At (Long_Float (K) * 0.1)), 0.0, 0.0)));
      end loop;
      Result.Robots.Append (Robot);
      Result.Plan_Time := 1.0;
      --  Lost at 20 s, still at (15, 0), with g2 at (15.2, 0) left to do.
      Tasks.Append (Missions.Mission_Task'
                      (Id => To_Unbounded_String ("g2"), Kind => Missions.Goto_Pose,
                       Points => Missions.Point_Vectors.To_Vector ((15.2, 0.0), 1)));
      Result.Killed := Robot.Id;
      Result.Kill_Time := 20.0;
      Result.Orphans.Append (TD.Completion'(Task_Id => To_Unbounded_String ("g2"), others => <>));
      Result.Completions.Append
        (TD.Completion'(To_Unbounded_String ("g1"), Robot.Id, 7.0, others => <>));
      Result.Completions.Append
        (TD.Completion'(To_Unbounded_String ("s1"), Robot.Id, 17.0, others => <>));
      TD.Note_Arrivals (Result, Tasks);
      declare
         R : TD.Robot_Summary renames Result.Robots (1);
      begin
         Assert (Near (Result.Completions (1).Reached, 6.5),
                 "g1 reached at" & Result.Completions (1).Reached'Image);
         Assert (Near (Result.Completions (2).Reached, 11.5),
                 "s1 entered at" & Result.Completions (2).Reached'Image);
         Assert (Natural (R.Stops.Length) = 2
                 and then Near (R.Stops (1).From, 0.0) and then Near (R.Stops (1).To, 2.0)
                 and then Near (R.Stops (2).From, 17.0) and then Near (R.Stops (2).To, 20.0),
                 "stops:" & R.Stops.Length'Image);
         Assert (Near (R.Travel, 9.0) and then Near (R.At_Task, 6.0)
                 and then Near (R.Stopped, 1.0),
                 "going" & R.Travel'Image & ", at tasks" & R.At_Task'Image & ", stopped"
                 & R.Stopped'Image);
         Assert (abs (R.Travel + R.At_Task + R.Stopped - 16.0) < 1.0E-9,
                 "parts add up to the last completion - the first plan");
         Assert (Result.Last_Leg.Robot = Robot.Id and then Result.Last_Leg.Task_Id = "g2"
                 and then Result.Last_Leg.Time = 20.0
                 and then Near (Result.Last_Leg.Reached, 17.0),
                 "last leg: " & To_String (Result.Last_Leg.Task_Id) & Result.Last_Leg.Time'Image
                 & Result.Last_Leg.Reached'Image);
      end;
      --  Turning on the spot is not standing still; a track that never
      --  comes near the task leaves Reached unknown.
      Result.Robots (1).Track.Clear;
      for K in 0 .. 50 loop
         Result.Robots (1).Track.Append
           (TD.Track_Sample'(Time => Long_Float (K) * 0.1,
                             Where => (20.0, 0.0, Geometry.Real (K) * 0.05)));
      end loop;
      Result.Completions.Delete_Last;
      TD.Note_Arrivals (Result, Tasks);
      Assert (Result.Robots (1).Stops.Is_Empty, "turning counted as stopped");
      Assert (Result.Completions (1).Reached < 0.0,
              "reached though never near:" & Result.Completions (1).Reached'Image);
      Assert (Result.Last_Leg.Robot = Robot.Id and then Result.Last_Leg.Reached < 0.0,
              "last leg reached though never near:" & Result.Last_Leg.Reached'Image);
   end Test_Arrivals;

   --  The demo end to end -----------------------------------------------------------------

   procedure Check_Demo (How : Agents.Method; Team : String) is
      Config : Commands.Team_Demos.Demo_Config;
      Result : Commands.Team_Demos.Demo_Result;
      M      : constant Missions.Mission := Missions.Read ("share/missions/office-team.xml");
   begin
      Config.Mission_File := To_Unbounded_String ("share/missions/office-team.xml");
      Config.How := How;
      Config.Rate := 40.0;
      Config.Run.Verbose := False;
      Config.Team := To_Unbounded_String (Team);
      Config.Run.Out_Dir := To_Unbounded_String ("out/test-" & Team);
      Commands.Team_Demos.Run (Config, Result);
      Assert (Result.Killed /= Null_Unbounded_String, "no robot was killed");
      Assert (Result.Replanned, "the survivors did not re-plan");
      Assert (Result.All_Done, "not all tasks done:" & Result.Tasks_Done'Image);
      for T of M.Tasks loop
         declare
            Count : Natural := 0;
         begin
            for C of Result.Completions loop
               if C.Task_Id = T.Id then
                  Count := Count + 1;
                  Assert (C.Robot /= Result.Killed or else C.Time <= Result.Kill_Time,
                          "task " & To_String (T.Id) & " done by the dead robot");
               end if;
            end loop;
            Assert (Count = 1, "task " & To_String (T.Id) & " done" & Count'Image & " times");
         end;
      end loop;
      Assert (Natural (Result.Completions.Length) = Natural (M.Tasks.Length),
              "completions:" & Result.Completions.Length'Image);
      Assert ((for all R of Result.Round_After.Robots => R.Id /= Result.Killed),
              "the dead robot is still in the new round");
   end Check_Demo;

   procedure Test_Demo_Annealer (T : in out Fixture) is
      pragma Unreferenced (T);
   begin
      Check_Demo (Agents.Annealing, "t_demo_ann");
   end Test_Demo_Annealer;

   procedure Test_Demo_Auctions (T : in out Fixture) is
      pragma Unreferenced (T);
   begin
      Check_Demo (Agents.Auctions, "t_demo_auc");
   end Test_Demo_Auctions;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
      procedure Add (Name : String; Proc : Caller.Test_Method) is
      begin
         Result.Add_Test (Caller.Create ("team: " & Name, Proc));
      end Add;
   begin
      Add ("network destinations and channels", Test_Destinations'Access);
      Add ("presence and loss after the lease", Test_Presence'Access);
      Add ("replicated database converges under concurrent writes", Test_Convergence'Access);
      Add ("late joiner gets the state", Test_Late_Joiner'Access);
      Add ("cut-off node catches up after rejoining", Test_Cut_And_Rejoin'Access);
      Add ("a join republishes own, joiner's and departed writers' entries",
           Test_Republish_Rule'Access);
      Add ("mission files", Test_Mission_Errors'Access);
      Add ("plans: greedy, annealer, text", Test_Plans'Access);
      Add ("plans: a re-plan starts from the previous plan carried over",
           Test_Carried_Over'Access);
      Add ("a robot joining gets tasks, tasks done stay done", Test_Join'Access);
      Add ("team_member sends a goal again after an idle spell", Test_Goal_Tracker'Access);
      Add ("allocation legs along A* on a coarsened grid", Test_Grid_Costs'Access);
      Add ("a robot agent costs the legs between tasks before the first round",
           Test_Legs_Before_Round'Access);
      Add ("time per task: going, at the task, stopped (Note_Arrivals)",
           Test_Arrivals'Access);
      Add ("demo with a robot lost (annealer)", Test_Demo_Annealer'Access);
      Add ("demo with a robot lost (auctions)", Test_Demo_Auctions'Access);
      --  Last: its agents' annealings go on for up to 3 s after it.
      Add ("a robot takes its task from the team's plan while it anneals",
           Test_Task_While_Annealing'Access);
      Result.Add_Test (Goal_Trackers.Contract_Tests.Suite);
      return Result;
   end Suite;

end Sancta.Team.Tests;
