with Ada.Exceptions;
with Ada.Long_Float_Text_IO;
with Ada.Strings.Fixed;
with Ada.Text_IO;
with System.Multiprocessors;
with Sancta.Runtime.Values;

package body Sancta.Team.Agents is

   use Ada.Real_Time;
   use Sancta.Geometry;
   use type Interfaces.Unsigned_64;
   use type Missions.Task_Kind;
   use type Grid_Costs.Cost_Access;

   Tick          : constant Duration := 0.02;
   Settle_Time   : constant Time_Span := Milliseconds (300);
   Bid_Deadline  : constant Time_Span := Milliseconds (1000);

   function Trim (N : Integer) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Two_Decimals (X : Long_Float) return String is
      --  X with two decimals for a log line ("0.25", "42.05"); beyond 1e15,
      --  as Real_Image writes it.
      Text : String (1 .. 24);
   begin
      if abs X >= 1.0E15 then
         return Runtime.Values.Real_Image (X);
      end if;
      Ada.Long_Float_Text_IO.Put (Text, X, Aft => 2, Exp => 0);
      return Ada.Strings.Fixed.Trim (Text, Ada.Strings.Left);
   end Two_Decimals;

   function Parse_Method (Text : String) return Method is
   begin
      if Text in "annealer" | "annealing" then
         return Annealing;
      elsif Text in "auction" | "auctions" then
         return Auctions;
      end if;
      raise Constraint_Error with
        "allocation method """ & Text & """: expected annealer or auctions";
   end Parse_Method;

   --  Protected boxes -------------------------------------------------------------

   protected body Bid_Box is
      procedure Open (Generation, Step : Natural) is
      begin
         Gen := Generation;
         Item := Step;
         N := 0;
         Winner := (others => <>);
      end Open;

      procedure Add (Generation, Step : Natural; B : Bid) is
      begin
         if Generation /= Gen or else Step /= Item then
            return;
         end if;
         N := N + 1;
         if B.Cost < Winner.Cost
           or else (B.Cost = Winner.Cost and then B.Robot < Winner.Robot)
         then
            Winner := B;
         end if;
      end Add;

      function Count return Natural is (N);
      function Best return Bid is (Winner);
   end Bid_Box;

   protected body View_Box is
      procedure Set (V : View) is
      begin
         Current := V;
      end Set;
      function Get return View is (Current);
   end View_Box;

   protected body Pose_Box is
      procedure Set (Where : Point) is
      begin
         Latest := (Where, True);
      end Set;

      procedure Take (Note : out Pose_Note) is
      begin
         Note := Latest;
         Latest.Pending := False;
      end Take;
   end Pose_Box;

   protected body Progress_Box is
      procedure Set (P : Progress) is
      begin
         Current := P;
      end Set;
      function Get return Progress is (Current);
   end Progress_Box;

   --  Helpers ---------------------------------------------------------------------

   function Split (Text : String; Sep : Character) return Name_Sets.Set is
      Result : Name_Sets.Set;
      First  : Positive := Text'First;
   begin
      for I in Text'First .. Text'Last + 1 loop
         if I > Text'Last or else Text (I) = Sep then
            if I > First then
               Result.Include (Text (First .. I - 1));
            end if;
            First := I + 1;
         end if;
      end loop;
      return Result;
   end Split;

   function Parse_Point (Text : String) return Point is
      Comma : constant Natural := Ada.Strings.Fixed.Index (Text, ",");
   begin
      return (Real'Value (Text (Text'First .. Comma - 1)),
              Real'Value (Text (Comma + 1 .. Text'Last)));
   end Parse_Point;

   function Img (X : Real) return String is (Runtime.Values.Real_Image (Long_Float (X)));

   function Is_Done (This : Agent'Class; Task_Id : String) return Boolean is
     (This.Db.Contains ("done/" & Task_Id) or else This.Steps.Get.Done.Contains (Task_Id));

   function Mission_Set (This : Agent'Class) return Name_Sets.Set is
     (Split (This.Db.Get_String ("mission"), ','));

   function Alive_Robots (This : Agent'Class) return Name_Sets.Set is
      Result : Name_Sets.Set;
   begin
      for M of This.Net.Members loop
         declare
            Id : constant String := To_String (M);
         begin
            if This.Db.Contains ("robot/" & Id) and then This.Db.Contains ("pose/" & Id) then
               Result.Include (Id);
            end if;
         end;
      end loop;
      return Result;
   end Alive_Robots;

   function Has_Quorum (This : Agent'Class) return Boolean is
      Round    : constant Plans.Snapshot := This.Views.Get.Round;
      Operator : constant String := This.Db.Writer ("mission");
      Voters   : Name_Sets.Set;
      Heard    : Natural := 0;
   begin
      if Round.Generation = 0 then
         return True;
      end if;
      for R of Round.Robots loop
         Voters.Include (To_String (R.Id));
      end loop;
      if Operator /= "" then
         Voters.Include (Operator);
      end if;
      for V of Voters loop
         if V = To_String (This.Config.Id) or else This.Net.Is_Member (V) then
            Heard := Heard + 1;
         end if;
      end loop;
      return 2 * Heard > Natural (Voters.Length);
   end Has_Quorum;

   function Round_Robots (S : Plans.Snapshot) return Name_Sets.Set is
      Result : Name_Sets.Set;
   begin
      for R of S.Robots loop
         Result.Include (To_String (R.Id));
      end loop;
      return Result;
   end Round_Robots;

   procedure Log (This : Agent'Class; Text : String) is
   begin
      if not This.Config.Verbose then
         return;
      end if;
      Ada.Text_IO.Put_Line
        (Ada.Text_IO.Standard_Error, "[" & To_String (This.Config.Id) & "] " & Text);
   end Log;

   --  Reading the round and the proposals ------------------------------------------

   function Tasks_Known (This : Agent'Class; Round_Text : String) return Boolean is
      --  Every task of the round is in this replica (a round may arrive
      --  before the task entries it names: the view waits for them).
      S   : Plans.Snapshot;
      Ids : Missions.Task_Vectors.Vector;
   begin
      Plans.Decode (Round_Text, S, Ids);
      return (for all T of Ids => This.Db.Contains ("task/" & To_String (T.Id)));
   end Tasks_Known;

   function Read_Round (This : Agent'Class) return Plans.Snapshot is
      S   : Plans.Snapshot;
      Ids : Missions.Task_Vectors.Vector;
   begin
      if not This.Db.Contains ("round") then
         return S;
      end if;
      Plans.Decode (This.Db.Get_String ("round"), S, Ids);
      for T of Ids loop
         S.Tasks.Append
           (Missions.Decode (To_String (T.Id), This.Db.Get_String ("task/" & To_String (T.Id))));
      end loop;
      return S;
   end Read_Round;

   function Best_Proposal (This : in out Agent'Class; S : Plans.Snapshot) return Plans.Plan is
      --  Every proposal is decoded once per (entry, round): the agent task
      --  calls this every tick, and 20 robots' plans of 200 tasks decoded
      --  50 times a second by 20 agents were a sixth of the work at scale.
      Best : Plans.Plan;
   begin
      for K of This.Db.Keys_With_Prefix ("proposal/") loop
         declare
            Seen : constant Proposal_Entry :=
              (Revision => This.Db.Revision (K),
               Writer   => To_Unbounded_String (This.Db.Writer (K)),
               Round    => S.Generation,
               others   => <>);
            Known : constant Proposal_Maps.Cursor := This.Proposals.Find (K);
         begin
            if not Proposal_Maps.Has_Element (Known)
              or else Proposal_Maps.Element (Known).Revision /= Seen.Revision
              or else Proposal_Maps.Element (Known).Writer /= Seen.Writer
              or else Proposal_Maps.Element (Known).Round /= Seen.Round
            then
               declare
                  Fresh : Proposal_Entry := Seen;
               begin
                  begin
                     Fresh.Proposal := Plans.Decode (This.Db.Get_String (K), S);
                     Fresh.Fits := Fresh.Proposal.Generation = S.Generation;
                  exception
                     when Plans.Format_Error =>
                        null;  --  a proposal for another round
                  end;
                  This.Proposals.Include (K, Fresh);
               end;
            end if;
            declare
               E : Proposal_Entry renames This.Proposals.Constant_Reference (K);
               P : Plans.Plan renames E.Proposal;
            begin
               if E.Fits
                 and then (Best.Generation = 0
                           or else P.Value < Best.Value
                           or else (P.Value = Best.Value and then P.Proposer < Best.Proposer))
               then
                  Best := P;
               end if;
            end;
         end;
      end loop;
      return Best;
   end Best_Proposal;

   procedure Refresh_View (This : in out Agent'Class) is
      Text : constant String := This.Db.Get_String ("round");
      V    : View := This.Views.Get;
   begin
      if Text = "" then
         return;
      end if;
      if Text /= To_String (This.Last_Round_Text) then
         if not Tasks_Known (This, Text) then
            return;  --  the round's task entries are still on their way
         end if;
         if V.Adopted.Generation /= 0 and then V.Adopted.Generation = V.Round.Generation then
            This.Previous := V;
         end if;
         V.Round := Read_Round (This);
         This.Last_Round_Text := To_Unbounded_String (Text);
         This.Improved_Rounds := 0;
         This.Proposals.Clear;
         V.Adopted := (others => <>);
      end if;
      declare
         Best : constant Plans.Plan := Best_Proposal (This, V.Round);
      begin
         if Best.Generation = V.Round.Generation then
            V.Adopted := Best;
         end if;
      end;
      This.Views.Set (V);
   end Refresh_View;

   --  Coordination -------------------------------------------------------------------

   procedure Run_Auctions (This : in out Agent'Class; S : Plans.Snapshot);

   procedure Coordinate (This : in out Agent'Class) is
      Alive    : constant Name_Sets.Set := Alive_Robots (This);
      Tasks    : constant Name_Sets.Set := Mission_Set (This);
      Current  : constant Plans.Snapshot := This.Views.Get.Round;
      In_Round : Name_Sets.Set;
      Needed   : Boolean;
   begin
      if Tasks.Is_Empty or else Alive.Is_Empty
        or else Clock - This.Started_At < To_Time_Span (2 * This.Config.Lease)
        or else Alive.First_Element /= To_String (This.Config.Id)
        or else (for all T of Tasks => Is_Done (This, T))
        or else not Has_Quorum (This)
      then
         --  Not the coordinator, nothing left to allocate, cut off from
         --  the majority (a minority side never re-plans), or started less
         --  than two leases ago: a node that has not yet heard the others
         --  would take itself for the coordinator and plan every task for
         --  itself alone (the 10-process demo: rounds of 1 robot at start).
         This.Mismatch_Since := Time_Last;
         return;
      end if;
      for T of Current.Tasks loop
         In_Round.Include (To_String (T.Id));
      end loop;
      Needed := Current.Generation = 0
        or else not Name_Sets."=" (Round_Robots (Current), Alive);
      if not Needed then
         for T of Tasks loop
            if not In_Round.Contains (T) and then not Is_Done (This, T) then
               Needed := True;
            end if;
         end loop;
      end if;
      if not Needed then
         This.Mismatch_Since := Time_Last;
         return;
      end if;
      if This.Mismatch_Since = Time_Last then
         This.Mismatch_Since := Clock;
         return;
      elsif Clock - This.Mismatch_Since < Settle_Time then
         return;
      end if;
      This.Mismatch_Since := Time_Last;
      declare
         S : Plans.Snapshot;
         Gen : constant Natural :=
           Natural'Max (Current.Generation,
                        Natural (This.Db.Revision ("round"))) + 1;
      begin
         S.Generation := Gen;
         for R of Alive loop
            S.Robots.Append
              (Plans.Robot_Position'(To_Unbounded_String (R),
                                     Parse_Point (This.Db.Get_String ("pose/" & R))));
         end loop;
         for T of Tasks loop
            if not Is_Done (This, T) then
               S.Tasks.Append (Missions.Decode (T, This.Db.Get_String ("task/" & T)));
            end if;
         end loop;
         Log (This, "round" & Gen'Image & ":" & S.Robots.Length'Image & " robots,"
              & S.Tasks.Length'Image & " tasks to allocate");
         This.Db.Put ("round", Plans.Encode (S));
         Refresh_View (This);
         if This.Config.How = Auctions then
            Run_Auctions (This, S);
         end if;
      end;
   end Coordinate;

   procedure Propose_In_Slot (This : in out Agent'Class; V : View);

   protected Anneal_Slots is
      --  The agents of one process share its processors: at most one
      --  annealer per processor runs at a time (20 robot agents in one
      --  process annealing together left each a twentieth of a processor
      --  for its budget, and starved the network tasks: leases lapsed).
      procedure Try_Seize (Got : out Boolean);
      procedure Release;
   private
      Free : Natural := Natural (System.Multiprocessors.Number_Of_CPUs);
   end Anneal_Slots;

   protected body Anneal_Slots is
      procedure Try_Seize (Got : out Boolean) is
      begin
         Got := Free > 0;
         if Got then
            Free := Free - 1;
         end if;
      end Try_Seize;

      procedure Release is
      begin
         Free := Free + 1;
      end Release;
   end Anneal_Slots;

   procedure Collect_Proposal (This : in out Agent'Class) is
      --  The outcome of the agent's annealing, when it has ended: published
      --  when it is still for the current round and better than the plan
      --  adopted and than the agent's carried-over proposal.
      Ready   : Boolean;
      Outcome : Anneal_Outcome;
   begin
      This.Jobs.Collect (Ready, Outcome);
      if not Ready then
         return;
      end if;
      This.Annealing := False;
      if This.Warming then
         This.Warming := False;
         Log (This, "legs between the mission's tasks costed in "
              & Two_Decimals (Long_Float (Outcome.Took)) & " s"
              & (if Outcome.Failure = Null_Unbounded_String then ""
                 else ": " & To_String (Outcome.Failure)));
         return;
      end if;
      if Outcome.Failure /= Null_Unbounded_String then
         --  As when the annealing ran in this task: logged, tried again.
         Log (This, "agent task: " & To_String (Outcome.Failure));
         return;
      end if;
      declare
         V    : constant View := This.Views.Get;
         Mine : Plans.Plan renames Outcome.Result;
      begin
         Log (This, "annealed round" & Mine.Generation'Image & " in "
              & Two_Decimals (Long_Float (Outcome.Took)) & " s, plan value "
              & Two_Decimals (Mine.Value));
         if Mine.Generation /= V.Round.Generation then
            return;  --  a new round opened meanwhile: this one is over
         end if;
         This.Improved_Rounds := This.Improved_Rounds + 1;
         if (V.Adopted.Generation /= Mine.Generation
             or else Mine.Value < V.Adopted.Value - 1.0E-6)
           and then Mine.Value < This.Job_Published - 1.0E-6
         then
            This.Db.Put ("proposal/" & To_String (This.Config.Id), Plans.Encode (Mine, V.Round));
         end if;
      end;
   end Collect_Proposal;

   procedure Warm_Legs (This : in out Agent'Class) is
      --  Before the first round (the coordinator opens none in its first
      --  two leases), once the mission and its tasks are known: has the
      --  Annealer cost the legs between every two tasks, the bulk of the
      --  first annealing's A* searches (1-5 s of wall time in the demo).
      Ids  : constant Name_Sets.Set := Mission_Set (This);
      Job  : Anneal_Job := (Kind => Warm_Legs, Costs => This.Config.Costs, others => <>);
      Got  : Boolean;
   begin
      if Ids.Is_Empty or else not (for all T of Ids => This.Db.Contains ("task/" & T)) then
         return;
      end if;
      Anneal_Slots.Try_Seize (Got);
      if not Got then
         return;
      end if;
      This.Warmed := True;
      begin
         for T of Ids loop
            Job.Round.Tasks.Append (Missions.Decode (T, This.Db.Get_String ("task/" & T)));
         end loop;
      exception
         when others =>
            Anneal_Slots.Release;
            raise;
      end;
      This.Jobs.Submit (Job);
      This.Annealing := True;
      This.Warming := True;
   end Warm_Legs;

   procedure Propose (This : in out Agent'Class) is
      V   : constant View := This.Views.Get;
      S   : Plans.Snapshot renames V.Round;
      Got : Boolean := False;
   begin
      if This.Annealing then
         Collect_Proposal (This);
         return;
      end if;
      if This.Config.How = Annealing and then This.Config.Costs /= null
        and then not This.Warmed and then S.Generation = 0
      then
         Warm_Legs (This);
         return;
      end if;
      if This.Config.How /= Annealing or else S.Generation = 0
        or else not Round_Robots (S).Contains (To_String (This.Config.Id))
        or else This.Improved_Rounds > This.Config.Rounds
      then
         return;
      end if;
      Anneal_Slots.Try_Seize (Got);
      if not Got then
         return;  --  another agent of this process anneals: next tick
      end if;
      Propose_In_Slot (This, V);
      --  The Annealer releases the slot when the job ends.
   exception
      when others =>
         if Got and then not This.Annealing then
            Anneal_Slots.Release;
         end if;
         raise;
   end Propose;

   procedure Propose_In_Slot (This : in out Agent'Class; V : View) is
      --  Publishes the carried-over start of a re-plan at once, then hands
      --  the annealing to the agent's Annealer task (Collect_Proposal takes
      --  its outcome in a later tick).
      S     : Plans.Snapshot renames V.Round;
      Seed  : constant Interfaces.Unsigned_64 :=
        This.Config.Seed * 1_000_003 + Interfaces.Unsigned_64 (S.Generation) * 7919
        + Interfaces.Unsigned_64 (This.Improved_Rounds);
      T0    : constant Time := Clock;
      function Leg (From, To : Point) return Long_Float is
        (This.Config.Costs.Leg (From, To));
      --  A re-plan starts from the plan the team follows (a lost robot's
      --  tasks inserted where they cost least), published at once: the team
      --  has a plan for the new round before any annealing.
      Carried : constant Plans.Plan :=
        (if This.Improved_Rounds > 0 then (others => <>)
         elsif This.Config.Costs = null
         then Plans.Carried_Over (This.Previous.Round, This.Previous.Adopted, S,
                                  To_String (This.Config.Id))
         else Plans.Carried_Over (This.Previous.Round, This.Previous.Adopted, S,
                                  To_String (This.Config.Id), Leg'Access));
      Start : constant Plans.Plan :=
        (if This.Improved_Rounds = 0 then Carried else V.Adopted);
   begin
      This.Job_Published := Long_Float'Last;
      if not Carried.Tours.Is_Empty
        and then (V.Adopted.Generation /= S.Generation
                  or else Carried.Value < V.Adopted.Value - 1.0E-6)
      then
         This.Job_Published := Carried.Value;
         This.Db.Put ("proposal/" & To_String (This.Config.Id), Plans.Encode (Carried, S));
         Log (This, "round" & S.Generation'Image & " starts from the current plan in "
              & Two_Decimals (Long_Float (To_Duration (Clock - T0))) & " s, plan value "
              & Two_Decimals (Carried.Value));
      end if;
      This.Jobs.Submit
        ((Kind     => Anneal,
          Round    => S,
          Seed     => Seed,
          Budget   => This.Config.Budget,
          Start    => Start,
          Proposer => This.Config.Id,
          Costs    => This.Config.Costs));
      This.Annealing := True;
   end Propose_In_Slot;

   --  Auctions (coordinator side) -------------------------------------------------------

   procedure Run_Auctions (This : in out Agent'Class; S : Plans.Snapshot) is
      function Leg (From, To : Point) return Long_Float is
        (This.Config.Costs.Leg (From, To));
      Result     : Plans.Plan := (Generation => S.Generation,
                                  Proposer => This.Config.Id, others => <>);
      Unassigned : Name_Sets.Set;
      Step       : Natural := 0;
      Failures   : Natural := 0;
      Dummy      : Long_Float;

      function Index_Of (Robot : String) return Natural is
      begin
         for R in 1 .. Natural (S.Robots.Length) loop
            if To_String (S.Robots (R).Id) = Robot then
               return R;
            end if;
         end loop;
         return 0;
      end Index_Of;
   begin
      for R in 1 .. Natural (S.Robots.Length) loop
         Result.Tours.Append (Plans.Step_Vectors.Empty_Vector);
      end loop;
      for T of S.Tasks loop
         Unassigned.Include (To_String (T.Id));
      end loop;
      while not Unassigned.Is_Empty loop
         exit when This.Stopping;
         Step := Step + 1;
         This.Bids.Open (S.Generation, Step);
         declare
            Offer : Unbounded_String :=
              To_Unbounded_String ("offer" & ASCII.LF & Trim (S.Generation) & ASCII.LF
                                   & Trim (Step) & ASCII.LF);
            Deadline : constant Time := Clock + Bid_Deadline;
         begin
            for T of Unassigned loop
               Append (Offer, T & ",");
            end loop;
            Append (Offer, ASCII.LF & Plans.Encode (S));
            This.Net.Send (Networks.To_Group ("robots"), "auction", To_String (Offer));
            while This.Bids.Count < Natural (S.Robots.Length) and then Clock < Deadline
              and then not This.Stopping
            loop
               delay 0.002;
            end loop;
         end;
         declare
            B : constant Bid := This.Bids.Best;
            R : constant Natural := Index_Of (To_String (B.Robot));
         begin
            if This.Bids.Count = 0 or else R = 0
              or else not Unassigned.Contains (To_String (B.Task_Id))
            then
               Failures := Failures + 1;
               if Failures >= 3 then
                  Log (This, "auctions of round" & S.Generation'Image & " abandoned (no bids)");
                  return;
               end if;
            else
               if B.Pos > Natural (Result.Tours (R).Length) + 1 then
                  Result.Tours (R).Append (Plans.Step'(B.Task_Id, B.Choice));
               else
                  Result.Tours (R).Insert (B.Pos, Plans.Step'(B.Task_Id, B.Choice));
               end if;
               Unassigned.Delete (To_String (B.Task_Id));
               declare
                  Tour : Unbounded_String;
               begin
                  for St of Result.Tours (R) loop
                     Append (Tour, St.Task_Id & "." & Trim (St.Choice) & ",");
                  end loop;
                  This.Net.Send
                    (Networks.To_Group ("robots"), "auction",
                     "award" & ASCII.LF & Trim (S.Generation) & ASCII.LF & Trim (Step) & ASCII.LF
                     & To_String (B.Robot) & ASCII.LF & To_String (Tour));
               end;
            end if;
         end;
      end loop;
      if This.Config.Costs = null then
         Dummy := Plans.Evaluate (S, Result);
      else
         Dummy := Plans.Evaluate (S, Result, Leg'Access);
      end if;
      This.Db.Put ("proposal/" & To_String (This.Config.Id), Plans.Encode (Result, S));
      Log (This, "auctions of round" & S.Generation'Image & " done in" & Step'Image & " steps");
   end Run_Auctions;

   --  Auctions (bidder side, in the network's task) -------------------------------------

   overriding procedure On_Message
     (This : in out Auction_Consumer; Sender, Channel, Payload : String)
   is
      pragma Unreferenced (Channel);
      A : Agent renames This.Owner.all;
      function Leg (From, To : Point) return Long_Float is (A.Config.Costs.Leg (From, To));
      type Line_Array is array (1 .. 6) of Unbounded_String;
      L : Line_Array;
      N : Natural := 0;
      First : Positive := Payload'First;
   begin
      for I in Payload'First .. Payload'Last + 1 loop
         if I > Payload'Last or else Payload (I) = ASCII.LF then
            exit when N = L'Last;
            N := N + 1;
            L (N) := To_Unbounded_String (Payload (First .. I - 1));
            First := I + 1;
         end if;
      end loop;
      if N < 4 then
         return;
      end if;
      declare
         Kind : constant String := To_String (L (1));
         Gen  : constant Natural := Natural'Value (To_String (L (2)));
         Step : constant Natural := Natural'Value (To_String (L (3)));
         Self : constant String := To_String (A.Config.Id);
      begin
         if Kind = "bid" and then N >= 4 then
            --  "bid / gen / step / robot task cost pos choice"
            declare
               Text  : constant String := To_String (L (4));
               Parts : array (1 .. 5) of Unbounded_String;
               K     : Natural := 0;
               Start : Positive := Text'First;
            begin
               for I in Text'First .. Text'Last + 1 loop
                  if I > Text'Last or else Text (I) = ' ' then
                     exit when K = Parts'Last;
                     K := K + 1;
                     Parts (K) := To_Unbounded_String (Text (Start .. I - 1));
                     Start := I + 1;
                  end if;
               end loop;
               if K = 5 then
                  A.Bids.Add (Gen, Step,
                              (Robot   => Parts (1),
                               Task_Id => Parts (2),
                               Cost    => Long_Float'Value (To_String (Parts (3))),
                               Pos     => Positive'Value (To_String (Parts (4))),
                               Choice  => Positive'Value (To_String (Parts (5)))));
               end if;
            end;
            return;
         end if;
         if Kind = "offer" and then N >= 5 and then A.Bundle_Gen /= Gen then
            --  The round travels with the offer (no wait for the database).
            declare
               Ids : Missions.Task_Vectors.Vector;
               R   : Plans.Snapshot;
            begin
               Plans.Decode (To_String (L (5)), R, Ids);
               for T of Ids loop
                  R.Tasks.Append
                    (Missions.Decode
                       (To_String (T.Id), A.Db.Get_String ("task/" & To_String (T.Id))));
               end loop;
               A.Bid_Round := R;
               A.Bundle_Gen := Gen;
               A.Bundle.Clear;
            end;
         end if;
         if A.Bundle_Gen /= Gen or else not Round_Robots (A.Bid_Round).Contains (Self) then
            return;  --  not in this round: no bid (the auctioneer skips us)
         end if;
         declare
            S     : Plans.Snapshot renames A.Bid_Round;
            Start : Point;
         begin
            for R of S.Robots loop
               if To_String (R.Id) = Self then
                  Start := R.Where;
               end if;
            end loop;
            if Kind = "offer" then
               declare
                  Offered : constant Name_Sets.Set := Split (To_String (L (4)), ',');
                  Best    : Bid := (Robot => A.Config.Id, others => <>);
               begin
                  for T of Offered loop
                     declare
                        Cost : Long_Float;
                        Pos, C : Positive;
                     begin
                        if A.Config.Costs = null then
                           Plans.Best_Insertion (S, Start, A.Bundle, T, Cost, Pos, C);
                        else
                           Plans.Best_Insertion (S, Start, A.Bundle, T, Cost, Pos, C,
                                                 Leg'Access);
                        end if;
                        if Cost < Best.Cost then
                           Best := (A.Config.Id, To_Unbounded_String (T), Cost, Pos, C);
                        end if;
                     end;
                  end loop;
                  if Best.Cost < Long_Float'Last then
                     A.Net.Send
                       (Networks.To_Node (Sender), "auction",
                        "bid" & ASCII.LF & Trim (Gen) & ASCII.LF & Trim (Step) & ASCII.LF
                        & Self & " " & To_String (Best.Task_Id) & " "
                        & Runtime.Values.Real_Image (Best.Cost) & " " & Trim (Best.Pos)
                        & " " & Trim (Best.Choice));
                  end if;
               end;
            elsif Kind = "award" and then N >= 5 and then To_String (L (4)) = Self then
               A.Bundle.Clear;
               for St of Split (To_String (L (5)), ',') loop
                  declare
                     Dot : constant Natural :=
                       Ada.Strings.Fixed.Index (St, ".", Going => Ada.Strings.Backward);
                  begin
                     A.Bundle.Append
                       (Plans.Step'(To_Unbounded_String (St (St'First .. Dot - 1)),
                                    Positive'Value (St (Dot + 1 .. St'Last))));
                  end;
               end loop;
            end if;
         end;
      end;
   exception
      when E : Constraint_Error | Plans.Format_Error =>
         --  Data from outside: the network drops it with a rate-limited
         --  warning.
         raise Networks.Malformed_Data with
           "auction payload from " & Sender & ": " & Ada.Exceptions.Exception_Message (E);
   end On_Message;

   --  The agent -----------------------------------------------------------------------

   package Agent_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Agent_Access);

   protected Registry is
      procedure Add (A : Agent_Access);
      function Find (Id : String) return Agent_Access;
   private
      Known : Agent_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Add (A : Agent_Access) is
      begin
         Known.Include (A.Id, A);
      end Add;

      function Find (Id : String) return Agent_Access is
        (if Known.Contains (Id) then Known.Element (Id) else null);
   end Registry;

   function Find (Id : String) return Agent_Access is (Registry.Find (Id));

   function Create (Config : Agent_Config) return Agent_Access is
      Net : constant Networks.Network_Access := Networks.Create
        (To_String (Config.Id), Groups => (if Config.Is_Robot then "robots" else "operators"),
         Lease => Config.Lease, Team => To_String (Config.Team));
      Db  : constant Replicated_Databases.Team_Database_Access :=
              new Replicated_Databases.Team_Database (Net);
   begin
      Db.Attach;
      return Create (Config, Net, Db);
   end Create;

   function Create
     (Config : Agent_Config;
      Net    : not null Networks.Network_Access;
      Db     : not null Replicated_Databases.Team_Database_Access) return Agent_Access
   is
      A : constant Agent_Access := new Agent;
   begin
      A.Config := Config;
      A.Started_At := Clock;
      A.Net := Net;
      A.Db := Db;
      A.Net.Subscribe ("auction", A.Auction'Unchecked_Access);
      A.Net.Start;
      if Config.Is_Robot then
         A.Db.Put ("robot/" & To_String (Config.Id), "robot");
      end if;
      if Config.Is_Robot then
         A.Anneals := new Annealer (A.Jobs'Access);
      end if;
      A.Runner := new Worker (A);
      A.Runner.Go;
      Registry.Add (A);
      return A;
   end Create;

   function Id (This : Agent) return String is (To_String (This.Config.Id));
   function Database (This : Agent) return Replicated_Databases.Team_Database_Access is (This.Db);
   function Network (This : Agent) return Networks.Network_Access is (This.Net);

   procedure Stop (This : in out Agent) is
   begin
      This.Stopping := True;
      This.Net.Stop;
   end Stop;

   procedure Publish_Mission (This : in out Agent; M : Missions.Mission) is
      Ids : Unbounded_String;
   begin
      for T of M.Tasks loop
         This.Db.Put ("task/" & To_String (T.Id), Missions.Encode (T));
         Append (Ids, (if Ids = Null_Unbounded_String then "" else ",") & T.Id);
      end loop;
      This.Db.Put ("mission", To_String (Ids));
   end Publish_Mission;

   procedure Set_Pose (This : in out Agent; Where : Point) is
   begin
      This.Poses.Set (Where);
   end Set_Pose;

   procedure Write_Pose (This : in out Agent'Class) is
      --  In the agent's task: the latest position, at most every
      --  Pose_Period.
      Note : Pose_Note;
   begin
      if Clock < This.Next_Pose_Write then
         return;
      end if;
      This.Poses.Take (Note);
      if Note.Pending then
         This.Db.Put ("pose/" & To_String (This.Config.Id),
                      Img (Note.Where.X) & "," & Img (Note.Where.Y));
         This.Next_Pose_Write := Clock + To_Time_Span (Pose_Period);
      end if;
   end Write_Pose;

   procedure Current_Goal
     (This    : in out Agent;
      Found   : out Boolean;
      Goal    : out Point;
      Task_Id : out Unbounded_String)
   is
      V    : constant View := This.Views.Get;
      P    : Progress := This.Steps.Get;
      Self : constant String := To_String (This.Config.Id);
   begin
      Found := False;
      Goal := (0.0, 0.0);
      Task_Id := Null_Unbounded_String;
      if V.Adopted.Generation = 0 then
         return;
      elsif not Has_Quorum (This) then
         --  Cut off: only the task under way is finished.
         if P.Active /= Null_Unbounded_String
           and then not Is_Done (This, To_String (P.Active))
           and then Plans.Has_Task (V.Round, To_String (P.Active))
         then
            declare
               T : constant Missions.Mission_Task := Plans.Task_Of (V.Round, To_String (P.Active));
            begin
               for R in 1 .. Natural (V.Round.Robots.Length) loop
                  if To_String (V.Round.Robots (R).Id) = Self
                    and then R <= Natural (V.Adopted.Tours.Length)
                  then
                     for St of V.Adopted.Tours (R) loop
                        if St.Task_Id = P.Active then
                           Found := True;
                           Task_Id := P.Active;
                           Goal := (if P.Phase = 1 then Missions.Entry_Point (T, St.Choice)
                                    else Missions.Exit_Point (T, St.Choice));
                        end if;
                     end loop;
                  end if;
               end loop;
            end;
         end if;
         return;
      end if;
      for R in 1 .. Natural (V.Round.Robots.Length) loop
         if To_String (V.Round.Robots (R).Id) = Self
           and then R <= Natural (V.Adopted.Tours.Length)
         then
            for St of V.Adopted.Tours (R) loop
               if not Is_Done (This, To_String (St.Task_Id)) then
                  declare
                     T : constant Missions.Mission_Task :=
                       Plans.Task_Of (V.Round, To_String (St.Task_Id));
                  begin
                     if P.Active /= St.Task_Id then
                        P.Active := St.Task_Id;
                        P.Phase := 1;
                        This.Steps.Set (P);
                     end if;
                     Found := True;
                     Task_Id := St.Task_Id;
                     Goal := (if P.Phase = 1 then Missions.Entry_Point (T, St.Choice)
                              else Missions.Exit_Point (T, St.Choice));
                     return;
                  end;
               end if;
            end loop;
         end if;
      end loop;
   end Current_Goal;

   procedure Arrived (This : in out Agent; Task_Id : String; Completed : out Boolean) is
      V : constant View := This.Views.Get;
      P : Progress := This.Steps.Get;
   begin
      Completed := False;
      if To_String (P.Active) /= Task_Id then
         return;
      end if;
      declare
         T : constant Missions.Mission_Task := Plans.Task_Of (V.Round, Task_Id);
      begin
         if P.Phase = 1 and then T.Kind = Missions.Explore_Segment then
            P.Phase := 2;
         else
            P.Done.Include (Task_Id);
            P.Active := Null_Unbounded_String;
            P.Phase := 0;
            Completed := True;
            This.Db.Put ("done/" & Task_Id, To_String (This.Config.Id));
         end if;
         This.Steps.Set (P);
      end;
   end Arrived;

   function Round (This : Agent) return Plans.Snapshot is (This.Views.Get.Round);
   function Adopted (This : Agent) return Plans.Plan is (This.Views.Get.Adopted);

   function Mission_Tasks (This : Agent) return Natural is
     (Natural (Mission_Set (This).Length));

   function Done_Tasks (This : Agent) return Natural is
      N : Natural := 0;
   begin
      for T of Mission_Set (This) loop
         if This.Db.Contains ("done/" & T) then
            N := N + 1;
         end if;
      end loop;
      return N;
   end Done_Tasks;

   function All_Done (This : Agent) return Boolean is
     (This.Mission_Tasks > 0 and then This.Done_Tasks = This.Mission_Tasks);

   protected body Anneal_Box is
      procedure Submit (Job : Anneal_Job) is
      begin
         Next := Job;
         Pending := True;
         Finished := False;
      end Submit;

      entry Take (Job : out Anneal_Job; Quit : out Boolean) when Pending or else Closing is
      begin
         Quit := Closing;
         if not Quit then
            Job := Next;
            Pending := False;
         end if;
      end Take;

      procedure Finish (Outcome : Anneal_Outcome) is
      begin
         Last := Outcome;
         Finished := True;
      end Finish;

      procedure Collect (Ready : out Boolean; Outcome : out Anneal_Outcome) is
      begin
         Ready := Finished;
         if Ready then
            Outcome := Last;
            Finished := False;
         end if;
      end Collect;

      procedure Shut is
      begin
         Closing := True;
      end Shut;
   end Anneal_Box;

   procedure Warm (S : Plans.Snapshot; Costs : not null Grid_Costs.Cost_Access) is
      --  Every leg Plans.Anneal costs between two task locations (each
      --  alternative's exit to every other one's entry), for the cache.
      function Count return Natural is
         N : Natural := 0;
      begin
         for T of S.Tasks loop
            N := N + Missions.Alternatives (T);
         end loop;
         return N;
      end Count;
      type Location is record
         Entry_At, Exit_At : Point;
      end record;
      Locations : array (1 .. Count) of Location;
      N         : Natural := 0;
      Dummy     : Long_Float;
   begin
      for T of S.Tasks loop
         for C in 1 .. Missions.Alternatives (T) loop
            N := N + 1;
            Locations (N) := (Missions.Entry_Point (T, C), Missions.Exit_Point (T, C));
         end loop;
      end loop;
      for A in Locations'Range loop
         for B in Locations'Range loop
            if A /= B then
               Dummy := Costs.Leg (Locations (A).Exit_At, Locations (B).Entry_At);
            end if;
         end loop;
      end loop;
   end Warm;

   task body Annealer is
      --  Runs the jobs its agent submits, each in the Anneal_Slots slot the
      --  agent task seized for it (released here when the job ends).
      Job  : Anneal_Job;
      Quit : Boolean;
   begin
      loop
         Jobs.Take (Job, Quit);
         exit when Quit;
         declare
            function Leg (From, To : Point) return Long_Float is (Job.Costs.Leg (From, To));
            T1      : constant Time := Clock;
            Outcome : Anneal_Outcome;
         begin
            begin
               if Job.Kind = Warm_Legs then
                  Warm (Job.Round, Job.Costs);
               else
                  Outcome.Result :=
                    (if Job.Costs = null
                     then Plans.Anneal (Job.Round, Job.Seed, Job.Budget, Job.Start,
                                        To_String (Job.Proposer))
                     else Plans.Anneal (Job.Round, Job.Seed, Job.Budget, Job.Start,
                                        To_String (Job.Proposer), Leg => Leg'Access));
               end if;
               Outcome.Took := To_Duration (Clock - T1);
            exception
               when E : others =>
                  Outcome.Failure :=
                    To_Unbounded_String (Ada.Exceptions.Exception_Information (E));
            end;
            Anneal_Slots.Release;
            Jobs.Finish (Outcome);
         end;
      end loop;
   end Annealer;

   task body Worker is
   begin
      accept Go;
      while not Owner.Stopping loop
         begin
            Owner.Db.Catch_Up;
            Write_Pose (Owner.all);
            Refresh_View (Owner.all);
            if Owner.Config.Is_Robot then
               Coordinate (Owner.all);
               Propose (Owner.all);
            end if;
         exception
            when E : others =>
               Log (Owner.all, "agent task: " & Ada.Exceptions.Exception_Information (E));
         end;
         delay Tick;
      end loop;
      Owner.Jobs.Shut;
   end Worker;

end Sancta.Team.Agents;
