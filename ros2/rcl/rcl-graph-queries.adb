with Ada.Containers.Generic_Array_Sort;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Containers.Ordered_Sets;
with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Streams;
with Ada.Strings.Fixed;
with Ada.Unchecked_Deallocation;
with Interfaces;
with RCL.DDS.Matching;
with RCL.Process_Context;

package body RCL.Graph.Queries is

   use Ada.Streams;
   use Interfaces;

   function Fully_Qualified (Node : Graph_Node) return String is
      NS : constant String := To_String (Node.Namespace);
   begin
      if NS = "/" or else NS = "" then
         return "/" & To_String (Node.Name);
      elsif NS (NS'Last) = '/' then
         return NS & To_String (Node.Name);
      else
         return NS & "/" & To_String (Node.Name);
      end if;
   end Fully_Qualified;

   --------------------
   -- Demangle_Topic --
   --------------------

   function Starts (S, Prefix : String) return Boolean is
     (S'Length >= Prefix'Length
      and then S (S'First .. S'First + Prefix'Length - 1) = Prefix);

   function Ends (S, Suffix : String) return Boolean is
     (S'Length >= Suffix'Length
      and then S (S'Last - Suffix'Length + 1 .. S'Last) = Suffix);

   procedure Demangle_Topic (DDS_Topic : String; Kind : out Name_Kind;
                             ROS_Name : out Unbounded_String) is
      S : String renames DDS_Topic;
   begin
      if Starts (S, "rt/") and S'Length > 3 then
         Kind := Topic;
         ROS_Name := To_Unbounded_String (S (S'First + 2 .. S'Last));
      elsif Starts (S, "rq/") and Ends (S, "Request") and S'Length > 10 then
         Kind := Request;
         ROS_Name := To_Unbounded_String (S (S'First + 2 .. S'Last - 7));
      elsif Starts (S, "rr/") and Ends (S, "Reply") and S'Length > 8 then
         Kind := Reply;
         ROS_Name := To_Unbounded_String (S (S'First + 2 .. S'Last - 5));
      else
         Kind := Other;
         ROS_Name := To_Unbounded_String (S);
      end if;
   end Demangle_Topic;

   -------------------
   -- Demangle_Type --
   -------------------

   function Demangle_Type (DDS_Type : String) return String is
      Marker : constant String := "::dds_::";
      At_M   : constant Natural := Ada.Strings.Fixed.Index (DDS_Type, Marker);
   begin
      if At_M = 0 or else not Ends (DDS_Type, "_") then
         return DDS_Type;
      end if;
      declare
         Head : constant String := DDS_Type (DDS_Type'First .. At_M - 1);
         --  "pkg::msg"
         Name : constant String := DDS_Type (At_M + Marker'Length .. DDS_Type'Last - 1);
         Sep  : constant Natural := Ada.Strings.Fixed.Index (Head, "::");
         Last : Natural := Name'Last;
      begin
         if Sep = 0 or else Name'Length = 0 then
            return DDS_Type;
         end if;
         if Ends (Name, "_Request") then
            Last := Name'Last - 8;
         elsif Ends (Name, "_Response") then
            Last := Name'Last - 9;
         end if;
         return Head (Head'First .. Sep - 1) & "/" & Head (Sep + 2 .. Head'Last) & "/"
           & Name (Name'First .. Last);
      end;
   end Demangle_Type;

   function Mangle_Type (ROS_Type : String) return String is
      First : constant Natural := Ada.Strings.Fixed.Index (ROS_Type, "/");
      Second : constant Natural :=
        (if First = 0 then 0
         else Ada.Strings.Fixed.Index (ROS_Type (First + 1 .. ROS_Type'Last), "/"));
   begin
      if Second = 0 then
         return ROS_Type;
      end if;
      return ROS_Type (ROS_Type'First .. First - 1) & "::"
        & ROS_Type (First + 1 .. Second - 1) & "::dds_::"
        & ROS_Type (Second + 1 .. ROS_Type'Last) & "_";
   end Mangle_Type;

   -----------------------------
   -- Decode_Participant_Info --
   -----------------------------

   Malformed : exception;

   function Decode_With
     (Data : RCL.DDS.Byte_Array; Gid_Size : Stream_Element_Offset) return Participant_Info
   is
      Little : constant Boolean := Data (Data'First + 1) = 1;
      Origin : constant Stream_Element_Offset := Data'First + 4;
      Pos    : Stream_Element_Offset := Origin;

      procedure Need (N : Stream_Element_Offset) is
      begin
         if N < 0 or else Pos + N - 1 > Data'Last then
            raise Malformed with "truncated at byte"
              & Stream_Element_Offset'Image (Pos - Data'First);
         end if;
      end Need;

      function U32 return Unsigned_32 is
         V : Unsigned_32 := 0;
      begin
         Pos := Origin + (Pos - Origin + 3) / 4 * 4;
         Need (4);
         for I in 0 .. 3 loop
            declare
               B : constant Unsigned_32 :=
                 Unsigned_32 (Data (Pos + Stream_Element_Offset (I)));
            begin
               V := V or Shift_Left (B, (if Little then 8 * I else 8 * (3 - I)));
            end;
         end loop;
         Pos := Pos + 4;
         return V;
      end U32;

      function Gid return RCL.DDS.GUID is
         G : RCL.DDS.GUID := [others => 0];
      begin
         Need (Gid_Size);
         for I in 1 .. 16 loop
            G (I) := Unsigned_8 (Data (Pos + Stream_Element_Offset (I - 1)));
         end loop;
         Pos := Pos + Gid_Size;
         return G;
      end Gid;

      function Str return String is
         Len : constant Unsigned_32 := U32;
      begin
         if Len = 0 or else Len > 257 then
            raise Malformed with "bad string length" & Len'Image & " at byte"
              & Stream_Element_Offset'Image (Pos - 4 - Data'First);
         end if;
         Need (Stream_Element_Offset (Len));
         declare
            S : String (1 .. Natural (Len) - 1);
         begin
            for I in S'Range loop
               S (I) := Character'Val (Data (Pos + Stream_Element_Offset (I - 1)));
            end loop;
            Pos := Pos + Stream_Element_Offset (Len);
            return S;
         end;
      end Str;

      function Gids return Unbounded_String is
         N : constant Unsigned_32 := U32;
         R : Unbounded_String;
      begin
         if Stream_Element_Offset (N) * Gid_Size > Data'Last - Pos + 1 then
            raise Malformed with "gid count" & N'Image & " exceeds the data at byte"
              & Stream_Element_Offset'Image (Pos - 4 - Data'First);
         end if;
         for I in 1 .. N loop
            Append (R, RCL.DDS.Image (Gid) & ",");
         end loop;
         return R;
      end Gids;

      Participant : constant RCL.DDS.GUID := Gid;
      Count       : constant Unsigned_32 := U32;
   begin
      if Stream_Element_Offset (Count) * 12 > Data'Last - Pos + 1 then
         raise Malformed with "node count" & Count'Image & " exceeds the data";
      end if;
      return Result : Participant_Info (Natural (Count)) do
         Result.Participant := Participant;
         for N of Result.Nodes loop
            N.Id.Namespace := To_Unbounded_String (Str);
            N.Id.Name := To_Unbounded_String (Str);
            N.Readers := Gids;
            N.Writers := Gids;
         end loop;
         if Data'Last - Pos + 1 > 3 then
            raise Malformed with Stream_Element_Offset'Image (Data'Last - Pos + 1)
              & " bytes left over at byte" & Stream_Element_Offset'Image (Pos - Data'First);
         end if;
      end return;
   end Decode_With;

   function Decode_Participant_Info (Data : RCL.DDS.Byte_Array) return Participant_Info is
   begin
      if Data'Length < 8 or else Data (Data'First) /= 0 or else Data (Data'First + 1) > 1 then
         raise ROS_Exception with "ros_discovery_info: no XCDR1 encapsulation header";
      end if;
      begin
         return Decode_With (Data, 24);
      exception
         when Malformed =>
            null;  --  Try the Jazzy layout.
      end;
      return Decode_With (Data, 16);
   exception
      when E : Malformed =>
         raise ROS_Exception with "ros_discovery_info: malformed sample: "
           & Ada.Exceptions.Exception_Message (E);
   end Decode_Participant_Info;

   ---------------------
   -- Discovery cache --
   ---------------------

   type Info_Access is access Participant_Info;
   procedure Free is new Ada.Unchecked_Deallocation (Participant_Info, Info_Access);

   package Info_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Info_Access);
   --  Participant GUID prefix image -> its latest announcement.

   function Prefix_Image (G : RCL.DDS.GUID) return String is
     (RCL.DDS.Image (G) (1 .. 35));
   --  The 12-byte participant prefix.

   Discovery_Profile : constant RCL.QoS.Profile :=
     (History => RCL.QoS.Keep_All, Durability => RCL.QoS.Transient_Local, others => <>);

   protected Discovery is
      procedure Refresh;
      --  Creates the reader on first use, takes what arrived.
      function Nodes_Of (Alive : String) return Node_Array;
      --  Nodes of participants whose prefix image occurs in Alive.
      function Owner_Of (Endpoint : RCL.DDS.GUID; Is_Writer : Boolean) return Graph_Node;
      function Announced (Prefix : String) return Boolean;
      --  A ros_discovery_info sample of the participant Prefix arrived.
   private
      Infos : Info_Maps.Map;
   end Discovery;

   Reader : RCL.DDS.Reader;

   protected body Discovery is

      procedure Refresh is
         Info : RCL.DDS.Sample_Info;
      begin
         if not RCL.DDS.Is_Open (Reader) then
            RCL.DDS.Create (Reader, RCL.Process_Context.Participant.all, Graph.Topic_Name,
                            Graph.Type_Name,
                            Discovery_Profile);
         end if;
         loop
            declare
               Data : constant RCL.DDS.Byte_Array := RCL.DDS.Take (Reader, Info);
            begin
               exit when Data'Length = 0;
               declare
                  P : constant Participant_Info := Decode_Participant_Info (Data);
                  K : constant String := Prefix_Image (P.Participant);
               begin
                  if Infos.Contains (K) then
                     declare
                        Old : Info_Access := Infos.Element (K);
                     begin
                        Free (Old);  --  (A peer re-announces on every change.)
                     end;
                  end if;
                  Infos.Include (K, new Participant_Info'(P));
               end;
            exception
               when ROS_Exception =>
                  null;  --  A malformed announcement is ignored.
            end;
         end loop;
      end Refresh;

      function Nodes_Of (Alive : String) return Node_Array is
         Count : Natural := 0;
      begin
         for C in Infos.Iterate loop
            if Ada.Strings.Fixed.Index (Alive, Info_Maps.Key (C)) > 0 then
               Count := Count + Info_Maps.Element (C).Count;
            end if;
         end loop;
         return Result : Node_Array (1 .. Count) do
            Count := 0;
            for C in Infos.Iterate loop
               if Ada.Strings.Fixed.Index (Alive, Info_Maps.Key (C)) > 0 then
                  for N of Info_Maps.Element (C).Nodes loop
                     Count := Count + 1;
                     Result (Count) := N.Id;
                  end loop;
               end if;
            end loop;
         end return;
      end Nodes_Of;

      function Owner_Of (Endpoint : RCL.DDS.GUID; Is_Writer : Boolean) return Graph_Node is
         Key : constant String := Prefix_Image (Endpoint);
         Img : constant String := RCL.DDS.Image (Endpoint) & ",";
      begin
         if Infos.Contains (Key) then
            for N of Infos.Element (Key).Nodes loop
               if Ada.Strings.Unbounded.Index
                    ((if Is_Writer then N.Writers else N.Readers), Img) > 0
               then
                  return N.Id;
               end if;
            end loop;
         end if;
         return (To_Unbounded_String (Unknown_Node_Name),
                 To_Unbounded_String (Unknown_Node_Namespace));
      end Owner_Of;

      function Announced (Prefix : String) return Boolean is (Infos.Contains (Prefix));

   end Discovery;

   procedure Wait_For_Discovery (Time : Duration) is
   begin
      Discovery.Refresh;
      delay Time;
      Discovery.Refresh;
   end Wait_For_Discovery;

   package Key_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);

   procedure Wait_For_Settled_Discovery
     (Least : Duration := 1.0; Quiet : Duration := 0.5; Limit : Duration := 5.0)
   is
      use Ada.Real_Time;
      use RCL.DDS.Matching;
      P     : constant not null access RCL.DDS.Participant := RCL.Process_Context.Participant;
      Own   : constant String := Prefix_Image (RCL.DDS.Instance_GUID (P.all));
      Start : constant Time := Clock;
      Last_Change : Time := Start;
      Last_State  : Unbounded_String;

      function State (Complete : out Boolean) return Unbounded_String is
         --  What was discovered of the others, as text (sorted: Cyclone's
         --  order varies);
         --  Complete: every ROS 2 participant announced its nodes.
         Keys   : Key_Sets.Set;
         Result : Unbounded_String;
      begin
         Complete := True;
         for Part of Builtin (P.all, Participants) loop
            declare
               Key : constant String := Prefix_Image (Part.Key);
            begin
               Keys.Include (Key);
               if Key /= Own
                 and then Ada.Strings.Fixed.Index (To_String (Part.User_Data), "enclave=") > 0
                 and then not Discovery.Announced (Key)
               then
                  Complete := False;
               end if;
            end;
         end loop;
         for Which in Publications .. Subscriptions loop
            for E of Builtin (P.all, Which) loop
               if Prefix_Image (E.Key) /= Own then
                  --  (Each Builtin call adds a reader of our own.)
                  Keys.Include (RCL.DDS.Image (E.Key));
               end if;
            end loop;
         end loop;
         for K of Keys loop
            Append (Result, K & ";");
         end loop;
         return Result;
      end State;

      Complete : Boolean;
   begin
      loop
         Discovery.Refresh;
         declare
            Now     : constant Time := Clock;
            Current : constant Unbounded_String := State (Complete);
         begin
            if Current /= Last_State then
               Last_State := Current;
               Last_Change := Now;
            end if;
            exit when Now - Start >= To_Time_Span (Limit);
            exit when Now - Start >= To_Time_Span (Least)
              and then Now - Last_Change >= To_Time_Span (Quiet)
              and then Complete;
         end;
         delay 0.05;
      end loop;
      Discovery.Refresh;
   end Wait_For_Settled_Discovery;

   function Alive_Participants return String is
      R : Unbounded_String;
   begin
      for P of RCL.DDS.Matching.Builtin
        (RCL.Process_Context.Participant.all, RCL.DDS.Matching.Participants)
      loop
         Append (R, Prefix_Image (P.Key) & " ");
      end loop;
      return To_String (R);
   end Alive_Participants;

   ----------------
   -- Node_Names --
   ----------------

   function "<" (L, R : Graph_Node) return Boolean is
     (Fully_Qualified (L) < Fully_Qualified (R));

   procedure Sort is new Ada.Containers.Generic_Array_Sort (Positive, Graph_Node, Node_Array);

   function Node_Names return Node_Array is
   begin
      Discovery.Refresh;
      declare
         Result : Node_Array := Discovery.Nodes_Of (Alive_Participants);
      begin
         Sort (Result);
         return Result;
      end;
   end Node_Names;

   ---------------
   -- Endpoints --
   ---------------

   function To_Profile (E : RCL.DDS.Matching.Endpoint) return RCL.QoS.Profile is
      use RCL.QoS;
      use type RCL.DDS.Time_Ns;
      function Seconds (T : RCL.DDS.Time_Ns) return Duration is
        (if T = RCL.DDS.Time_Ns'Last or else T <= 0 then 0.0
         elsif T > 1_000_000_000 * 86_400 then 86_400.0
         else Duration (T / 1_000_000_000) + Duration (T mod 1_000_000_000) / 1_000_000_000);
      --  Whole seconds first: Duration (T) would overflow beyond ~9.2e9 ns.
   begin
      return P : Profile do
         P.History := (case E.History is when 0 => Keep_Last, when 1 => Keep_All,
                       when others => RCL.QoS.Middleware_Default);
         P.Depth := Positive'Max (1, E.Depth);
         P.Reliability := (case E.Reliability is when 0 => Best_Effort, when 1 => Reliable,
                           when others => RCL.QoS.Middleware_Default);
         P.Durability := (case E.Durability is when 0 => Volatile,
                          when 1 => Transient_Local, when others => RCL.QoS.Middleware_Default);
         P.Deadline := Seconds (E.Deadline);
         P.Lifespan := Seconds (E.Lifespan);
         P.Liveliness := (case E.Liveliness is when 0 => Automatic, when 2 => Manual_By_Topic,
                          when others => RCL.QoS.Middleware_Default);
         if E.Lease /= RCL.DDS.Time_Ns'Last and E.Lease > 0 then
            P.Lease := Seconds (E.Lease);
         end if;
      end return;
   end To_Profile;

   function All_Endpoints return Endpoint_Array is
      use RCL.DDS.Matching;
      P      : constant not null access RCL.DDS.Participant := RCL.Process_Context.Participant;
      Pubs   : constant RCL.DDS.Matching.Endpoint_Array := Builtin (P.all, Publications);
      Subs   : constant RCL.DDS.Matching.Endpoint_Array := Builtin (P.all, Subscriptions);
      Result : Queries.Endpoint_Array (1 .. Pubs'Length + Subs'Length);
      N      : Natural := 0;

      procedure Add (E : RCL.DDS.Matching.Endpoint; Kind : Endpoint_Kind) is
         K    : Name_Kind;
         Name : Unbounded_String;
      begin
         Demangle_Topic (To_String (E.Topic_Name), K, Name);
         if K = Other then
            return;  --  Not a ROS name (ros_discovery_info, DDS-only topics).
         end if;
         N := N + 1;
         Result (N) :=
           (Kind       => Kind,
            Topic_Name => Name,
            Type_Name  => To_Unbounded_String (Demangle_Type (To_String (E.Type_Name))),
            DDS_Topic  => E.Topic_Name,
            DDS_Type   => E.Type_Name,
            Node       => Discovery.Owner_Of (E.Key, Kind = Publisher),
            GID        => E.Key,
            QoS        => To_Profile (E),
            User_Data  => E.User_Data);
      end Add;
   begin
      Discovery.Refresh;
      for E of Pubs loop
         Add (E, Publisher);
      end loop;
      for E of Subs loop
         Add (E, Subscription);
      end loop;
      return Result (1 .. N);
   end All_Endpoints;

   function Filter
     (From : Endpoint_Array; Kinds : String; Topic : String := "";
      Kind : Endpoint_Kind := Publisher; Any_Kind : Boolean := True) return Endpoint_Array
   is
      --  Kinds: "t" topics, "s" services (by DDS prefix).
      Result : Endpoint_Array (1 .. From'Length);
      N      : Natural := 0;
   begin
      for E of From loop
         declare
            Prefix : constant String := Slice (E.DDS_Topic, 1, 2);
            Ok     : constant Boolean :=
              ((Prefix = "rt" and Ada.Strings.Fixed.Index (Kinds, "t") > 0)
               or ((Prefix = "rq" or Prefix = "rr")
                   and Ada.Strings.Fixed.Index (Kinds, "s") > 0))
              and (Topic = "" or else To_String (E.Topic_Name) = Topic)
              and (Any_Kind or else E.Kind = Kind);
         begin
            if Ok then
               N := N + 1;
               Result (N) := E;
            end if;
         end;
      end loop;
      return Result (1 .. N);
   end Filter;

   function Topic_Endpoints return Endpoint_Array is (Filter (All_Endpoints, "t"));

   function Publishers_Info (Topic : String) return Endpoint_Array is
     (Filter (All_Endpoints, "t", Topic, Publisher, False));
   function Subscriptions_Info (Topic : String) return Endpoint_Array is
     (Filter (All_Endpoints, "t", Topic, Subscription, False));
   function Count_Publishers (Topic : String) return Natural is
     (Publishers_Info (Topic)'Length);
   function Count_Subscribers (Topic : String) return Natural is
     (Subscriptions_Info (Topic)'Length);

   function Node_Endpoints (Node : Graph_Node) return Endpoint_Array is
      From   : constant Endpoint_Array := All_Endpoints;
      Result : Endpoint_Array (1 .. From'Length);
      N      : Natural := 0;
   begin
      for E of From loop
         if Fully_Qualified (E.Node) = Fully_Qualified (Node) then
            N := N + 1;
            Result (N) := E;
         end if;
      end loop;
      return Result (1 .. N);
   end Node_Endpoints;

   ---------------------
   -- Names and types --
   ---------------------

   package String_Sets is new Ada.Containers.Ordered_Sets (Unbounded_String);
   package Type_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (String, String_Sets.Set, "<", String_Sets."=");

   function Collect (From : Endpoint_Array; Services : Boolean) return Name_And_Types_Array is
      Map : Type_Maps.Map;
   begin
      for E of From loop
         declare
            K    : Name_Kind;
            Name : Unbounded_String;
         begin
            Demangle_Topic (To_String (E.DDS_Topic), K, Name);
            if (not Services and K = Topic)
              or (Services and ((K = Request and E.Kind = Subscription)
                                or (K = Reply and E.Kind = Publisher)))
            then
               if not Map.Contains (To_String (Name)) then
                  Map.Insert (To_String (Name), String_Sets.Empty_Set);
               end if;
               Map.Reference (To_String (Name)).Include (E.Type_Name);
            end if;
         end;
      end loop;
      return Result : Name_And_Types_Array (1 .. Natural (Map.Length)) do
         declare
            I : Natural := 0;
         begin
            for C in Map.Iterate loop
               I := I + 1;
               Result (I).Name := To_Unbounded_String (Type_Maps.Key (C));
               for T of Type_Maps.Element (C) loop
                  if Length (Result (I).Types) > 0 then
                     Append (Result (I).Types, ", ");
                  end if;
                  Append (Result (I).Types, T);
               end loop;
            end loop;
         end;
      end return;
   end Collect;

   function Topic_Names_And_Types return Name_And_Types_Array is
     (Collect (All_Endpoints, Services => False));

   function Service_Names_And_Types return Name_And_Types_Array is
     (Collect (All_Endpoints, Services => True));

end RCL.Graph.Queries;
