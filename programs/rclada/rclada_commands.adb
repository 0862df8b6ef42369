with Ada.Characters.Latin_1;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Float_Text_IO;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Maps;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with ROSIDL.CDR;
with ROSIDL.Definitions.Rendering;
with ROSIDL.Dynamic;
with ROSIDL.Interfaces;
with ROSIDL.Typesupport;
with RCL.Clients;
with RCL.Clocks;
with RCL.Contexts;
with RCL.DDS;
with RCL.Graph.Queries;
with RCL.Names;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with RCL.Timers;
with RCL.YAML.Messages;
with Sancta.Edit_Distances;

package body Rclada_Commands is

   use Ada.Strings.Unbounded;
   use Ada.Text_IO;
   use type Ada.Real_Time.Time;

   package Graph renames RCL.Graph.Queries;

   LF : constant Character := Ada.Characters.Latin_1.LF;

   -----------
   -- Usage --
   -----------

   function Usage (Verb : String) return String is
   begin
      if Verb = "node" then
         return "usage: rclada node list [-a|--all] [--spin-time S]" & LF
           & "       rclada node info NODE_NAME [--spin-time S]" & LF
           & "  list: the fully qualified names of the nodes on the network" & LF
           & "  info: a node's publishers, subscribers, service servers and clients" & LF
           & "  Discovery is awaited until it settles (1 to 5 s); --spin-time S waits S.";
      elsif Verb = "topic" then
         return "usage: rclada topic list [-t|--show-types] [--spin-time S]" & LF
           & "       rclada topic info TOPIC [-v|--verbose]" & LF
           & "       rclada topic echo TOPIC [TYPE] [--once] [--count N] [--best-effort]" & LF
           & "       rclada topic pub TOPIC TYPE 'YAML' [--once] [--rate HZ] [--times N]" & LF
           & "       rclada topic hz TOPIC [TYPE] [--count N] [--window N]" & LF
           & "       rclada topic bw TOPIC [--window N]     rclada topic delay TOPIC" & LF
           & "       rclada topic type TOPIC                rclada topic find TYPE" & LF
           & "  TYPE: pkg/msg/Name (or pkg/Name); YAML: the message's fields," & LF
           & "  e.g. '{data: hello}' or '{linear: {x: 1.0}}'. pub publishes at 1 Hz" & LF
           & "  until Ctrl-C unless --once or --times is given.";
      elsif Verb = "service" then
         return "usage: rclada service list [-t|--show-types] [--spin-time S]" & LF
           & "       rclada service call SERVICE TYPE ['YAML'] [--timeout S]" & LF
           & "       rclada service type SERVICE            rclada service find TYPE" & LF
           & "  TYPE: pkg/srv/Name; YAML: the request's fields, e.g. '{a: 1, b: 2}'";
      elsif Verb = "param" then
         return "usage: rclada param list NODE_NAME" & LF
           & "       rclada param get NODE_NAME PARAMETER" & LF
           & "       rclada param set NODE_NAME PARAMETER VALUE" & LF
           & "       rclada param describe NODE_NAME PARAMETER" & LF
           & "       rclada param dump NODE_NAME   (YAML for --params-file)  [--timeout S]" & LF
           & "       rclada param delete NODE_NAME PARAMETER" & LF
           & "       rclada param load NODE_NAME FILE   (a --params-file YAML)" & LF
           & "  through the node's ~/list_parameters, ~/get_parameters and" & LF
           & "  ~/set_parameters services; VALUE is YAML (1, 2.5, true, text, [1, 2])";
      elsif Verb = "action" then
         return "usage: rclada action list [-t|--show-types] [--spin-time S]" & LF
           & "       rclada action info ACTION [-t|--show-types]" & LF
           & "       rclada action type ACTION" & LF
           & "       rclada action send_goal ACTION TYPE 'YAML' [-f|--feedback] [-s|--status]"
           & " [--timeout S]" & LF
           & "  TYPE: pkg/action/Name; YAML: the goal's fields, e.g. '{order: 5}';" & LF
           & "  --status: the goal's status changes (the action's status topic)";
      elsif Verb = "lifecycle" then
         return "usage: rclada lifecycle nodes [--spin-time S]" & LF
           & "       rclada lifecycle get NODE_NAME" & LF
           & "       rclada lifecycle set NODE_NAME TRANSITION   (configure, activate...)" & LF
           & "       rclada lifecycle list NODE_NAME [-a|--all]" & LF
           & "  through the managed node's ~/get_state, ~/change_state,"
           & " ~/get_available_transitions services";
      elsif Verb = "interface" then
         return "usage: rclada interface show TYPE" & LF
           & "       rclada interface list [-m|--only-msgs] [-s|--only-srvs] [-a|--only-actions]"
           & LF
           & "       rclada interface package PACKAGE" & LF
           & "  TYPE: pkg/msg/Name, pkg/srv/Name or pkg/action/Name";
      elsif Verb = "bag" then
         return "usage: rclada bag record (-a | TOPIC...) [-o DIR] [--duration S]"
           & " [-b|--max-bag-size BYTES]" & LF
           & "                         [-d|--max-bag-duration S] [--compression none|zstd|lz4]"
           & " [--include-hidden-topics]" & LF
           & "                         [--compression-mode file|message"
           & " --compression-format zstd]" & LF
           & "       rclada bag info BAG [--recover]" & LF
           & "       rclada bag play BAG [-r|--rate R] [-l|--loop] [--clock [HZ]]"
           & " [--topics TOPIC...] [--delay S]" & LF
           & "  BAG: a rosbag2 directory (metadata.yaml, *.mcap or *.db3, also zstd-"
           & "compressed)" & LF & "  or one such file." & LF
           & "  --compression-mode: rosbag2's zstd of each file (bag_0.mcap.zstd) or"
           & " message." & LF
           & "  record stops at Ctrl-C or after --duration; -b / -d start a new file" & LF
           & "  at that size / span. play keeps the recorded timing (scaled by --rate)" & LF
           & "  and with --clock publishes /clock (default 40 Hz).";
      elsif Verb = "security" then
         return "usage: rclada security create_keystore DIR" & LF
           & "       rclada security create_enclave DIR /ENCLAVE" & LF
           & "       rclada security create_permission DIR /ENCLAVE POLICY.xml" & LF
           & "       rclada security list_enclaves DIR" & LF
           & "  SROS2 keystores (openssl). A process is secured with" & LF
           & "  ROS_SECURITY_ENABLE=true ROS_SECURITY_KEYSTORE=DIR" & LF
           & "  [ROS_SECURITY_STRATEGY=Enforce] and --ros-args --enclave /ENCLAVE.";
      else
         return "usage: rclada VERB ... (rclada VERB --help for details)" & LF
           & "  node       list | info NODE" & LF
           & "  topic      list [-t] | info | echo | pub | hz | bw | delay | type | find" & LF
           & "  service    list [-t] | call NAME TYPE 'YAML' | type | find" & LF
           & "  param      list | get | set | describe | dump | delete | load" & LF
           & "  interface  show TYPE | list | package PKG" & LF
           & "  action     list [-t] | info | type | send_goal NAME TYPE 'YAML' [-f]" & LF
           & "  lifecycle  nodes | get NODE | set NODE TRANSITION | list NODE" & LF
           & "  security   create_keystore | create_enclave | create_permission | list_enclaves"
           & LF
           & "  bag        record (-a | TOPIC...) [-o DIR] | info BAG | play BAG [--rate R]" & LF
           & "The network is the one of ROS_DOMAIN_ID (CYCLONEDDS_URI, ROS_LOCALHOST_ONLY).";
      end if;
   end Usage;

   ---------------------
   -- Argument helpers --
   ---------------------

   function Has_Flag (Args : Arguments; Short, Long : String) return Boolean is
     (for some A of Args => A = Short or else A = Long);

   function Option (Args : Arguments; Name : String; Default : String) return String is
   begin
      for I in Args.First_Index .. Args.Last_Index loop
         if Args (I) = Name then
            if I = Args.Last_Index then
               raise Usage_Error with Name & " needs a value";
            end if;
            return Args (I + 1);
         end if;
      end loop;
      return Default;
   end Option;

   generic
      type Real is digits <>;
   function Number_In (Name, Image : String; Low, High : Real) return Real;
   --  Image, the value of option Name, as a number in Low .. High (so no
   --  infinity, NaN or value the caller cannot convert); Usage_Error
   --  "NAME: 'IMAGE' is not a number" or "NAME: IMAGE is out of range (LOW .. HIGH)".

   function Number_In (Name, Image : String; Low, High : Real) return Real is
      package Real_IO is new Ada.Text_IO.Float_IO (Real);
      Value : Real;

      function Bound (X : Real) return String is
         Text : String (1 .. 40);
      begin
         if X = Real'Floor (X) and then abs X <= 1.0e9 then
            return Ada.Strings.Fixed.Trim (Long_Long_Integer (X)'Image, Ada.Strings.Left);
         end if;
         Real_IO.Put (Text, X, Aft => 3, Exp => (if abs X < 0.001 then 2 else 0));
         return Ada.Strings.Fixed.Trim (Text, Ada.Strings.Left);
      end Bound;
   begin
      begin
         Value := Real'Value (Image);
         if not Value'Valid then
            raise Constraint_Error;  --  An infinity or NaN.
         end if;
      exception
         when Constraint_Error =>
            raise Usage_Error with Name & ": '" & Image & "' is not a number";
      end;
      if not (Value >= Low and then Value <= High) then
         raise Usage_Error with Name & ": " & Image & " is out of range ("
           & Bound (Low) & " .. " & Bound (High) & ")";
      end if;
      return Value;
   end Number_In;

   function Float_Number is new Number_In (Float);
   function Long_Float_Number is new Number_In (Long_Float);

   function Number_Option
     (Args : Arguments; Name : String; Default : String;
      Low  : Float := 0.0; High : Float := 1.0e6) return Float
   is (Float_Number (Name, Option (Args, Name, Default), Low, High));
   --  The value of option Name (Default when absent), a number in Low .. High.

   Valued_Options : constant array (1 .. 7) of Unbounded_String :=
     [To_Unbounded_String ("--spin-time"), To_Unbounded_String ("--count"),
      To_Unbounded_String ("--rate"), To_Unbounded_String ("--times"),
      To_Unbounded_String ("--window"), To_Unbounded_String ("--timeout"),
      To_Unbounded_String ("--wait")];

   procedure Split (Args : Arguments; Options, Operands : out Arguments) is
      --  Options: the option names in Args (a valued option's value
      --  skipped); Operands: the arguments that are neither.
      Skip : Boolean := False;
   begin
      for A of Args loop
         if Skip then
            Skip := False;
         elsif A'Length > 1 and then A (A'First) = '-'
           and then not (A (A'First + 1) in '0' .. '9' | '.')
         then
            Options.Append (A);
            Skip := (for some V of Valued_Options => To_String (V) = A);
         else
            Operands.Append (A);
         end if;
      end loop;
   end Split;

   function Positional (Args : Arguments) return Arguments is
      --  The arguments that are neither options nor option values.
      Options, Result : Arguments;
   begin
      Split (Args, Options, Result);
      return Result;
   end Positional;

   procedure Check_Options (Args : Arguments; Allowed : String) is
      --  Allowed: space-separated option names.
      Options, Operands : Arguments;
   begin
      Split (Args, Options, Operands);
      for A of Options loop
         if Ada.Strings.Fixed.Index (" " & Allowed & " ", " " & A & " ") = 0 then
            raise Usage_Error with "unknown option " & A;
         end if;
      end loop;
   end Check_Options;

   procedure Discover (Args : Arguments) is
      --  --spin-time S waits S; by default the wait lasts until discovery
      --  has settled (Wait_For_Settled_Discovery: 1 to 5 s).
   begin
      if Option (Args, "--spin-time", "") /= "" then
         Graph.Wait_For_Discovery (Duration (Number_Option (Args, "--spin-time", "1.0")));
      else
         Graph.Wait_For_Settled_Discovery;
      end if;
   end Discover;

   procedure Output_Closed is
   --  The reader of our standard output is gone ("rclada topic hz /x | head"):
   --  stop quietly, as a command ending its output.
   begin
      RCL.Contexts.Shutdown;
   end Output_Closed;

   function Tool_Node return RCL.Nodes.Node is
      function Getpid return Integer with Import, Convention => C, External_Name => "getpid";
      Pid : constant String := Integer'Image (Getpid);
   begin
      return RCL.Nodes.Init ("_rclada_" & Pid (Pid'First + 1 .. Pid'Last),
                             Options => (Start_Parameter_Services => False,
                                         Use_Global_Arguments     => False,
                                         others                   => <>));
   end Tool_Node;

   -----------------
   -- Type names --
   -----------------

   type Kind_Part is (Msg_Part, Srv_Part, Action_Part);

   function Part_Name (K : Kind_Part) return String is
     (case K is when Msg_Part => "msg", when Srv_Part => "srv", when Action_Part => "action");

   function Type_Names (Package_Name : String; Kind : Kind_Part)
     return ROSIDL.Definitions.String_Vectors.Vector
   is (case Kind is
          when Msg_Part => ROSIDL.Interfaces.Messages (Package_Name),
          when Srv_Part => ROSIDL.Interfaces.Services (Package_Name),
          when Action_Part => ROSIDL.Interfaces.Actions (Package_Name));
   --  The names of the package's interfaces of that kind.

   procedure Split_Type
     (Name : String; Kind : Kind_Part; Pkg, Base : out Unbounded_String)
   is
      First : constant Natural := Ada.Strings.Fixed.Index (Name, "/");
      Last  : constant Natural := Ada.Strings.Fixed.Index (Name, "/", Ada.Strings.Backward);
   begin
      if First = 0 or else First = Name'First or else Last = Name'Last then
         raise Command_Error with "'" & Name & "' is not a type name (pkg/"
           & Part_Name (Kind) & "/Name)";
      end if;
      if First /= Last and then Name (First + 1 .. Last - 1) /= Part_Name (Kind) then
         raise Command_Error with "'" & Name & "': expected a ." & Part_Name (Kind) & " type";
      end if;
      Pkg := To_Unbounded_String (Name (Name'First .. First - 1));
      Base := To_Unbounded_String (Name (Last + 1 .. Name'Last));
   end Split_Type;

   function Suggestions (Name : String; Kind : Kind_Part) return String is
      type Pick is record
         Name : Unbounded_String;
         Dist : Natural := Natural'Last;
      end record;
      Best : array (1 .. 3) of Pick;
   begin
      for P of ROSIDL.Interfaces.Packages loop
         for N of Type_Names (P, Kind) loop
            declare
               Full : constant String := P & "/" & Part_Name (Kind) & "/" & N;
               D    : constant Natural := Sancta.Edit_Distances.Distance (Name, Full);
            begin
               for I in Best'Range loop
                  if D < Best (I).Dist then
                     Best (I + 1 .. Best'Last) := Best (I .. Best'Last - 1);
                     Best (I) := (To_Unbounded_String (Full), D);
                     exit;
                  end if;
               end loop;
            end;
         end loop;
      end loop;
      declare
         R : Unbounded_String;
      begin
         for B of Best loop
            if B.Dist < Natural'Last then
               Append (R, (if Length (R) = 0 then "" else ", ") & B.Name);
            end if;
         end loop;
         return (if Length (R) = 0 then "" else " (did you mean: " & To_String (R) & "?)");
      end;
   end Suggestions;

   function Resolve_Message_Type (Name : String) return String is
      Pkg, Base : Unbounded_String;
   begin
      Split_Type (Name, Msg_Part, Pkg, Base);
      declare
         Def : constant ROSIDL.Definitions.Message_Access :=
           ROSIDL.Interfaces.Message (To_String (Pkg), To_String (Base));
      begin
         return ROSIDL.Definitions.Full_Name (Def.all);
      end;
   exception
      when ROSIDL.Unknown_Type =>
         raise Command_Error with "unknown message type '" & Name & "'"
           & Suggestions (Name, Msg_Part);
      when E : ROSIDL.Definition_Error =>
         raise Command_Error with "cannot read the definition of '" & Name & "': "
           & Ada.Exceptions.Exception_Message (E);
   end Resolve_Message_Type;

   function Message_Support (Name : String) return ROSIDL.Typesupport.Message_Support is
      Full : constant String := Resolve_Message_Type (Name);
      Pkg, Base : Unbounded_String;
   begin
      Split_Type (Full, Msg_Part, Pkg, Base);
      return ROSIDL.Typesupport.Get_Message_Support (To_String (Pkg), To_String (Base));
   end Message_Support;

   function Service_Support (Name : String) return ROSIDL.Typesupport.Service_Support is
      Pkg, Base : Unbounded_String;
   begin
      Split_Type (Name, Srv_Part, Pkg, Base);
      return ROSIDL.Typesupport.Get_Service_Support (To_String (Pkg), To_String (Base));
   exception
      when ROSIDL.Unknown_Type =>
         raise Command_Error with "unknown service type '" & Name & "'"
           & Suggestions (Name, Srv_Part);
   end Service_Support;

   procedure Put_Block (Text : String) is
      --  Text and one line end (Image results already end with one).
   begin
      if Text'Length > 0 and then Text (Text'Last) = LF then
         Put (Text);
      else
         Put_Line (Text);
      end if;
   end Put_Block;

   function Indented (Text : String; Prefix : String := "    ") return String is
      --  Text with Prefix before each of its lines.
      Result : Unbounded_String;
      At_Start : Boolean := True;
   begin
      for C of Text loop
         if At_Start and then C /= LF then
            Append (Result, Prefix);
         end if;
         Append (Result, C);
         At_Start := C = LF;
      end loop;
      return To_String (Result);
   end Indented;

   procedure Put_Lines (Text : String) is
      --  Text without its trailing empty lines, ending with one line end.
      Last : Natural := Text'Last;
   begin
      while Last >= Text'First and then Text (Last) = LF loop
         Last := Last - 1;
      end loop;
      Put_Line (Text (Text'First .. Last));
   end Put_Lines;

   function Fully_Qualified (Name : String) return String is
     (if Name'Length > 0 and then Name (Name'First) = '/' then Name else "/" & Name);

   subtype Command_Line_Name is String
     with Dynamic_Predicate =>
       RCL.Names.Topic_Problem (Fully_Qualified (Command_Line_Name)) = ""
       or else raise Command_Error with "invalid name '" & Command_Line_Name & "': "
                 & RCL.Names.Topic_Problem (Fully_Qualified (Command_Line_Name));
   --  A topic or service name from the command line: valid once fully
   --  qualified (an invalid name would be waited for forever).

   function Checked_Name (Name : Command_Line_Name) return RCL.Names.Topic_Name is
     (Fully_Qualified (Name));
   --  Name, fully qualified.

   function Message_From (Support : ROSIDL.Typesupport.Message_Support; Text : String)
      return ROSIDL.Dynamic.Message is
   begin
      return RCL.YAML.Messages.From_YAML (Support, Text, "<argument>");
   exception
      when E : RCL.YAML.Parse_Error =>
         raise Command_Error with "bad message: " & Ada.Exceptions.Exception_Message (E);
   end Message_From;

   --  Single-line rendering of a message ("ros2 ... pub" prints the request).
   function One_Line (Msg : ROSIDL.Dynamic.Message) return String is
      Text : constant String := ROSIDL.Dynamic.Image (Msg);
      R    : Unbounded_String;
   begin
      for C of Text loop
         if C = LF then
            Append (R, "; ");
         else
            Append (R, C);
         end if;
      end loop;
      declare
         S : constant String := To_String (R);
      begin
         if S'Length >= 2 and then S (S'Last - 1 .. S'Last) = "; " then
            return S (S'First .. S'Last - 2);
         end if;
         return S;
      end;
   end One_Line;

   ----------
   -- Node --
   ----------

   procedure Node_Command (Args : Arguments) is
      Pos : constant Arguments := Positional (Args);
   begin
      Check_Options (Args, "--spin-time -a --all");
      if Pos.Is_Empty then
         raise Usage_Error with "missing sub-command (list, info)";
      elsif Pos (1) = "list" then
         Discover (Args);
         for N of Graph.Node_Names loop
            --  Hidden nodes (name starting with '_', like this tool's own)
            --  only with --all, as ros2 node list does.
            if Has_Flag (Args, "-a", "--all") or else Element (N.Name, 1) /= '_' then
               Put_Line (Graph.Fully_Qualified (N));
            end if;
         end loop;
      elsif Pos (1) = "info" then
         if Natural (Pos.Length) /= 2 then
            raise Usage_Error with "node info takes one node name";
         end if;
         Discover (Args);
         declare
            Wanted : constant String := Fully_Qualified (Pos (2));
            Found  : Boolean := False;
         begin
            for N of Graph.Node_Names loop
               if Graph.Fully_Qualified (N) = Wanted then
                  Found := True;
                  declare
                     E : constant Graph.Endpoint_Array := Graph.Node_Endpoints (N);
                     procedure Section (Title, Prefix : String; Kind : Graph.Endpoint_Kind) is
                        use type Graph.Endpoint_Kind;
                     begin
                        Put_Line ("  " & Title & ":");
                        for X of E loop
                           if X.Kind = Kind and then Slice (X.DDS_Topic, 1, 2) = Prefix then
                              Put_Line ("    " & To_String (X.Topic_Name) & ": "
                                        & To_String (X.Type_Name));
                           end if;
                        end loop;
                     end Section;
                  begin
                     Put_Line (Wanted);
                     Section ("Subscribers", "rt", Graph.Subscription);
                     Section ("Publishers", "rt", Graph.Publisher);
                     Section ("Service Servers", "rq", Graph.Subscription);
                     Section ("Service Clients", "rq", Graph.Publisher);
                     Put_Line ("  Action Servers:");
                     Put_Line ("  Action Clients:");
                     --  Actions are not listed yet (no action support in RCL).
                  end;
               end if;
            end loop;
            if not Found then
               raise Command_Error with "Unable to find node '" & Wanted & "'";
            end if;
         end;
      else
         raise Usage_Error with "unknown node sub-command '" & Pos (1) & "'";
      end if;
   end Node_Command;

   -----------
   -- Topic --
   -----------

   function Topic_Type (Topic : String; Args : Arguments) return String is
      --  The type of Topic's publishers (after discovery).
   begin
      Discover (Args);
      for Attempt in 1 .. 50 loop
         declare
            P : constant Graph.Endpoint_Array := Graph.Publishers_Info (Topic);
         begin
            if P'Length > 0 then
               return To_String (P (P'First).Type_Name);
            end if;
         end;
         delay 0.1;
      end loop;
      raise Command_Error with "could not determine the type of " & Topic
        & " (no publisher seen): give it as TYPE";
   end Topic_Type;

   procedure Topic_List (Args : Arguments) is
      Types : constant Boolean := Has_Flag (Args, "-t", "--show-types");
   begin
      Discover (Args);
      for T of Graph.Topic_Names_And_Types loop
         if Types then
            Put_Line (To_String (T.Name) & " [" & To_String (T.Types) & "]");
         else
            Put_Line (To_String (T.Name));
         end if;
      end loop;
   end Topic_List;

   function QoS_Text (P : RCL.QoS.Profile) return String is
      use RCL.QoS;
      function Img (D : Duration) return String is
        (if D = 0.0 or else D >= 86_400.0 then "Infinite"
         else Long_Long_Integer'Image (Long_Long_Integer (D * 1.0E9)) & " nanoseconds");
   begin
      return "  QoS profile:" & LF
        & "    Reliability: " & (case P.Reliability is
             when Reliable => "RELIABLE", when Best_Effort => "BEST_EFFORT",
             when others => "UNKNOWN") & LF
        & "    History (Depth): " & (case P.History is
             when Keep_Last => "KEEP_LAST (" & Ada.Strings.Fixed.Trim (P.Depth'Image,
                                                                      Ada.Strings.Left) & ")",
             when Keep_All => "KEEP_ALL", when others => "UNKNOWN") & LF
        & "    Durability: " & (case P.Durability is
             when Volatile => "VOLATILE", when Transient_Local => "TRANSIENT_LOCAL",
             when others => "UNKNOWN") & LF
        & "    Lifespan: " & Img (P.Lifespan) & LF
        & "    Deadline: " & Img (P.Deadline) & LF
        & "    Liveliness: " & (case P.Liveliness is
             when Automatic => "AUTOMATIC", when Manual_By_Topic => "MANUAL_BY_TOPIC",
             when others => "MANUAL_BY_PARTICIPANT") & LF
        & "    Liveliness lease duration: "
        & (if P.Lease >= 86_400.0 then "Infinite" else Img (P.Lease));
   end QoS_Text;

   procedure Topic_Info (Topic : String; Args : Arguments) is
      Verbose : constant Boolean := Has_Flag (Args, "-v", "--verbose");
   begin
      Discover (Args);
      declare
         Pubs : constant Graph.Endpoint_Array := Graph.Publishers_Info (Topic);
         Subs : constant Graph.Endpoint_Array := Graph.Subscriptions_Info (Topic);
         Type_Name : Unbounded_String;

         procedure Show (E : Graph.Endpoint_Array; Kind : String) is
         begin
            for X of E loop
               Put_Line ("Node name: " & To_String (X.Node.Name));
               Put_Line ("Node namespace: " & To_String (X.Node.Namespace));
               Put_Line ("Topic type: " & To_String (X.Type_Name));
               Put_Line ("Endpoint type: " & Kind);
               Put_Line ("GID: " & RCL.DDS.Image (X.GID));
               Put_Line (QoS_Text (X.QoS));
               New_Line;
            end loop;
         end Show;
      begin
         if Pubs'Length + Subs'Length = 0 then
            raise Command_Error with "Unknown topic '" & Topic & "'";
         end if;
         Type_Name := (if Pubs'Length > 0 then Pubs (Pubs'First).Type_Name
                       else Subs (Subs'First).Type_Name);
         Put_Line ("Type: " & To_String (Type_Name));
         if Verbose then
            New_Line;
         end if;
         Put_Line ("Publisher count:" & Pubs'Length'Image);
         if Verbose then
            New_Line;
            Show (Pubs, "PUBLISHER");
         end if;
         Put_Line ("Subscription count:" & Subs'Length'Image);
         if Verbose then
            New_Line;
            Show (Subs, "SUBSCRIPTION");
         end if;
      end;
   end Topic_Info;

   procedure Topic_Echo (Topic : String; Type_Arg : String; Args : Arguments) is
      Type_Name : constant String :=
        (if Type_Arg /= "" then Resolve_Message_Type (Type_Arg) else Topic_Type (Topic, Args));
      Support   : constant ROSIDL.Typesupport.Message_Support := Message_Support (Type_Name);
      Limit     : constant Natural :=
        (if Has_Flag (Args, "--once", "--once") then 1
         elsif Option (Args, "--count", "") /= ""
         then Natural (Number_Option (Args, "--count", "1", Low => 1.0, High => 1.0e9))
         else 0);
      --  0: until Ctrl-C; an explicit --count is at least 1.
      Seen      : Natural := 0;
      QoS       : constant RCL.QoS.Profile :=
        (if Has_Flag (Args, "--best-effort", "--best-effort") then RCL.QoS.Sensor_Data
         else RCL.QoS.Default);
      Node      : RCL.Nodes.Node := Tool_Node;

      procedure On_Data
        (Node : in out RCL.Nodes.Node'Class;
         Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Info);
      begin
         if Limit > 0 and then Seen >= Limit then
            return;  --  Taken with the last one before the shutdown took effect.
         end if;
         Put_Block (ROSIDL.Dynamic.Image (ROSIDL.CDR.Decode (Support, Data)));
         Put_Line ("---");
         Flush;
         Seen := Seen + 1;
         if Limit > 0 and then Seen >= Limit then
            RCL.Contexts.Shutdown;
         end if;
      exception
         when E : ROSIDL.Decode_Error =>
            Put_Line (Standard_Error, "malformed sample skipped: "
                      & Ada.Exceptions.Exception_Message (E));
         when Ada.IO_Exceptions.Device_Error =>
            Output_Closed;
      end On_Data;
   begin
      Node.Subscribe_Raw (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic,
                          On_Data'Access, QoS);
      Node.Spin;
   end Topic_Echo;

   procedure Topic_Pub
     (Topic, Type_Arg, Text : String; Has_Message : Boolean; Args : Arguments)
   is
      --  Text: the YAML message when the command line has one (Has_Message);
      --  without, the default message (bounded publications only).
      Support : constant ROSIDL.Typesupport.Message_Support := Message_Support (Type_Arg);
      Msg     : constant ROSIDL.Dynamic.Message :=
        Message_From (Support, (if Has_Message then Text else "{}"));
      Rate    : constant Float := Number_Option (Args, "--rate", "1.0", Low => 0.001);
      Times   : constant Natural :=
        (if Option (Args, "--times", "") /= ""
         then Natural (Number_Option (Args, "--times", "1", Low => 1.0, High => 1.0e9))
         elsif Has_Flag (Args, "-1", "--once") then 1
         else 0);
      --  0: until Ctrl-C ("--times -1" is a range error, not --times and -1).
      Node    : RCL.Nodes.Node := Tool_Node;
      Pub     : constant RCL.Publishers.Publisher :=
        Node.Publish_Raw (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic);
      Bytes   : constant RCL.DDS.Byte_Array := ROSIDL.CDR.Encode (Msg);
      Period  : constant Ada.Real_Time.Time_Span :=
        Ada.Real_Time.To_Time_Span (Duration (1.0 / Rate));
      Next    : Ada.Real_Time.Time;
      Count   : Natural := 0;
      Wait_Until : constant Ada.Real_Time.Time :=
        Ada.Real_Time.Clock
        + Ada.Real_Time.To_Time_Span (Duration (Number_Option (Args, "--wait", "1.0")));
   begin
      if Rate <= 0.0 then
         raise Usage_Error with "--rate must be positive";
      elsif not Has_Message and then Times = 0 then
         raise Usage_Error with "topic pub: no YAML message: give one ('{data: hello}', '{}'"
           & " for the default message) or publish a bounded number (--once, --times N)";
      end if;
      RCL.Contexts.Install_Signal_Handlers;
      Put_Line ("publisher: beginning loop");
      --  Give subscribers a moment to match (as ros2 topic pub waits for
      --  matching subscriptions).
      while Pub.Matched_Subscriptions = 0 and then Ada.Real_Time.Clock < Wait_Until loop
         delay 0.01;
      end loop;
      Next := Ada.Real_Time.Clock;
      while not RCL.Contexts.Is_Shutdown loop
         Count := Count + 1;
         Pub.Publish_Raw (Bytes);
         Put_Line ("publishing #" & Ada.Strings.Fixed.Trim (Count'Image, Ada.Strings.Left)
                   & ": " & ROSIDL.Dynamic.Type_Name (Msg) & "(" & One_Line (Msg) & ")");
         New_Line;
         Flush;
         exit when Times > 0 and then Count >= Times;
         Next := Next + Period;
         delay until Next;
      end loop;
      --  Let reliable data reach late readers before the writer goes.
      delay 0.2;
   end Topic_Pub;

   procedure Topic_Hz (Topic : String; Type_Arg : String; Args : Arguments) is
      Window    : constant Positive :=
        Positive (Number_Option (Args, "--window", "10000", 1.0, 1.0e7));
      Reports   : constant Natural :=
        Natural (Number_Option (Args, "--count", "0", High => 1.0e9));
      --  The options first: a bad value is said before the wait for a publisher.
      Type_Name : constant String :=
        (if Type_Arg /= "" then Resolve_Message_Type (Type_Arg) else Topic_Type (Topic, Args));
      Support   : constant ROSIDL.Typesupport.Message_Support := Message_Support (Type_Name);
      Reported  : Natural := 0;
      Node      : RCL.Nodes.Node := Tool_Node;
      Times     : array (1 .. Window) of Ada.Real_Time.Time;
      N         : Natural := 0;
      Head      : Natural := 0;
      Last_Seen : Natural := 0;

      procedure On_Data
        (Node : in out RCL.Nodes.Node'Class;
         Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Data, Info);
      begin
         Head := Head mod Window + 1;
         Times (Head) := Ada.Real_Time.Clock;
         N := Natural'Min (N + 1, Window);
         Last_Seen := Last_Seen + 1;
      end On_Data;

      procedure On_Timer
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration)
      is
         pragma Unreferenced (Node, Timer, Elapsed);
         use Ada.Numerics.Long_Elementary_Functions;
         Sum, Sum2 : Long_Float := 0.0;
         Min_D     : Long_Float := Long_Float'Last;
         Max_D     : Long_Float := 0.0;
         function Fmt (X : Long_Float; Digits_After : Natural) return String is
            package F is new Ada.Text_IO.Float_IO (Long_Float);
            S : String (1 .. 40);
         begin
            F.Put (S, X, Aft => Digits_After, Exp => 0);
            return Ada.Strings.Fixed.Trim (S, Ada.Strings.Both);
         end Fmt;
      begin
         if N < 2 then
            Put_Line ("no new messages");
            Flush;
            return;
         end if;
         for K in 1 .. N - 1 loop
            declare
               I  : constant Positive := (Head - K - 1 + 2 * Window) mod Window + 1;
               J  : constant Positive := (Head - K + 2 * Window) mod Window + 1;
               Dt : constant Long_Float :=
                 Long_Float (Ada.Real_Time.To_Duration (Times (J) - Times (I)));
            begin
               Sum := Sum + Dt;
               Sum2 := Sum2 + Dt * Dt;
               Min_D := Long_Float'Min (Min_D, Dt);
               Max_D := Long_Float'Max (Max_D, Dt);
            end;
         end loop;
         declare
            Count : constant Long_Float := Long_Float (N - 1);
            Mean  : constant Long_Float := Sum / Count;
            Var   : constant Long_Float := Long_Float'Max (0.0, Sum2 / Count - Mean * Mean);
         begin
            Put_Line ("average rate: " & Fmt ((if Mean > 0.0 then 1.0 / Mean else 0.0), 3));
            Put_Line (Ada.Characters.Latin_1.HT & "min: " & Fmt (Min_D, 3) & "s max: "
                      & Fmt (Max_D, 3) & "s std dev: " & Fmt (Sqrt (Var), 5) & "s window: "
                      & Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));
            Flush;
         end;
         Reported := Reported + 1;
         if Reports > 0 and then Reported >= Reports then
            RCL.Contexts.Shutdown;
         end if;
      exception
         when Ada.IO_Exceptions.Device_Error =>
            Output_Closed;
      end On_Timer;
   begin
      Node.Subscribe_Raw (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic, On_Data'Access);
      Node.Timer_Add (1.0, On_Timer'Access);
      Node.Spin;
   end Topic_Hz;

   procedure Graph_Verbs (Verb : String; Args : Arguments);

   procedure Topic_Command (Args : Arguments) is
      Pos : constant Arguments := Positional (Args);
      function Arg (I : Positive) return String is
        (if Natural (Pos.Length) >= I then Pos (I) else "");
   begin
      if Pos.Is_Empty then
         raise Usage_Error with
           "missing sub-command (list, info, echo, pub, hz, bw, delay, type, find)";
      elsif Pos (1) = "list" then
         Check_Options (Args, "-t --show-types --spin-time");
         Topic_List (Args);
      elsif Pos (1) = "info" then
         Check_Options (Args, "-v --verbose --spin-time");
         if Natural (Pos.Length) /= 2 then
            raise Usage_Error with "topic info takes one topic name";
         end if;
         Topic_Info (Checked_Name (Arg (2)), Args);
      elsif Pos (1) = "echo" then
         Check_Options (Args, "--once --count --best-effort --spin-time");
         if Natural (Pos.Length) not in 2 .. 3 then
            raise Usage_Error with "topic echo takes a topic name and optionally a type";
         end if;
         Topic_Echo (Checked_Name (Arg (2)), Arg (3), Args);
      elsif Pos (1) = "pub" then
         Check_Options (Args, "--once -1 --rate --times --wait");
         if Natural (Pos.Length) not in 3 .. 4 then
            raise Usage_Error with "topic pub takes a topic name, a type and a YAML message";
         end if;
         Topic_Pub (Checked_Name (Arg (2)), Arg (3), Arg (4), Natural (Pos.Length) = 4, Args);
      elsif Pos (1) = "hz" then
         Check_Options (Args, "--count --window --spin-time");
         if Natural (Pos.Length) not in 2 .. 3 then
            raise Usage_Error with "topic hz takes a topic name and optionally a type";
         end if;
         Topic_Hz (Checked_Name (Arg (2)), Arg (3), Args);
      elsif Pos (1) in "type" | "find" | "bw" | "delay" then
         Graph_Verbs ("topic", Args);
      else
         raise Usage_Error with "unknown topic sub-command '" & Pos (1) & "'";
      end if;
   end Topic_Command;

   -------------
   -- Service --
   -------------

   procedure Service_Command (Args : Arguments) is
      Pos : constant Arguments := Positional (Args);
   begin
      if Pos.Is_Empty then
         raise Usage_Error with "missing sub-command (list, call)";
      elsif Pos (1) = "list" then
         Check_Options (Args, "-t --show-types --spin-time");
         Discover (Args);
         for S of Graph.Service_Names_And_Types loop
            if Has_Flag (Args, "-t", "--show-types") then
               Put_Line (To_String (S.Name) & " [" & To_String (S.Types) & "]");
            else
               Put_Line (To_String (S.Name));
            end if;
         end loop;
      elsif Pos (1) = "call" then
         Check_Options (Args, "--timeout");
         if Natural (Pos.Length) not in 3 .. 4 then
            raise Usage_Error
              with "service call takes a service name, a type and optionally a request";
         end if;
         declare
            Support : constant ROSIDL.Typesupport.Service_Support := Service_Support (Pos (3));
            Request : constant ROSIDL.Dynamic.Message :=
              Message_From (ROSIDL.Typesupport.Request_Support (Support),
                            (if Natural (Pos.Length) = 4 then Pos (4) else "{}"));
            Timeout : constant Duration :=
              Duration (Number_Option (Args, "--timeout", "10.0"));
            Node    : constant RCL.Nodes.Node := Tool_Node;
            Client  : RCL.Clients.Client;
         begin
            Client.Init (Node, Support, Checked_Name (Pos (2)));
            if not Client.Wait_For_Service (Timeout) then
               raise Command_Error with "service " & Fully_Qualified (Pos (2))
                 & " not available after" & Timeout'Image & " s";
            end if;
            Put_Line ("requester: making request: "
                      & ROSIDL.Dynamic.Type_Name (Request) & "(" & One_Line (Request) & ")");
            New_Line;
            declare
               Response : constant ROSIDL.Dynamic.Message := Client.Call (Request, Timeout);
            begin
               Put_Line ("response:");
               Put_Block (ROSIDL.Dynamic.Image (Response));
            end;
         exception
            when E : RCL.RCL_Timeout =>
               raise Command_Error with Ada.Exceptions.Exception_Message (E);
         end;
      elsif Pos (1) in "type" | "find" then
         Graph_Verbs ("service", Args);
      else
         raise Usage_Error with "unknown service sub-command '" & Pos (1) & "'";
      end if;
   end Service_Command;

   -----------
   -- Param --
   -----------

   procedure Param_Command (Args : Arguments) is separate;

   procedure Action_Command (Args : Arguments) is separate;

   procedure Graph_Verbs (Verb : String; Args : Arguments) is separate;
   --  topic type | find | bw | delay, service type | find.

   procedure Lifecycle_Command (Args : Arguments) is separate;

   procedure Security_Command (Args : Arguments) is separate;

   procedure Bag_Command (Args : Arguments) is separate;

   ---------------
   -- Interface --
   ---------------

   procedure Interface_Command (Args : Arguments) is
      Pos : constant Arguments := Positional (Args);
   begin
      if Pos.Is_Empty then
         raise Usage_Error with "missing sub-command (show, list, package)";
      elsif Pos (1) = "show" then
         Check_Options (Args, "");
         if Natural (Pos.Length) /= 2 then
            raise Usage_Error with "interface show takes one type name";
         end if;
         declare
            Name : constant String := Pos (2);
            Kind : constant Kind_Part :=
              (if Ada.Strings.Fixed.Index (Name, "/srv/") > 0 then Srv_Part
               elsif Ada.Strings.Fixed.Index (Name, "/action/") > 0 then Action_Part
               else Msg_Part);
            Pkg, Base : Unbounded_String;
         begin
            Split_Type (Name, Kind, Pkg, Base);
            case Kind is
               when Msg_Part =>
                  Put_Lines (ROSIDL.Definitions.Rendering.Show
                       (ROSIDL.Interfaces.Message (To_String (Pkg), To_String (Base)).all));
               when Srv_Part =>
                  Put_Lines (ROSIDL.Definitions.Rendering.Show
                       (ROSIDL.Interfaces.Service (To_String (Pkg), To_String (Base)).all));
               when Action_Part =>
                  Put_Lines (ROSIDL.Definitions.Rendering.Show
                       (ROSIDL.Interfaces.Action (To_String (Pkg), To_String (Base)).all));
            end case;
         exception
            when ROSIDL.Unknown_Type =>
               raise Command_Error with "unknown interface type '" & Name & "'"
                 & Suggestions (Name, Kind);
         end;
      elsif Pos (1) = "list" or else Pos (1) = "package" then
         Check_Options (Args, "-m --only-msgs -s --only-srvs -a --only-actions");
         declare
            Only_M : constant Boolean := Has_Flag (Args, "-m", "--only-msgs");
            Only_S : constant Boolean := Has_Flag (Args, "-s", "--only-srvs");
            Only_A : constant Boolean := Has_Flag (Args, "-a", "--only-actions");
            All_K  : constant Boolean := not (Only_M or Only_S or Only_A);
            One    : constant String :=
              (if Pos (1) = "package" and then Natural (Pos.Length) = 2 then Pos (2) else "");
            Found  : Boolean := One = "";
            procedure Show_Kind (Title : String; Kind : Kind_Part) is
            begin
               if One = "" then
                  Put_Line (Title & ":");
               end if;
               for P of ROSIDL.Interfaces.Packages loop
                  if One = "" or else P = One then
                     Found := Found or P = One;
                     for N of Type_Names (P, Kind) loop
                        Put_Line ((if One = "" then "    " else "")
                                  & P & "/" & Part_Name (Kind) & "/" & N);
                     end loop;
                  end if;
               end loop;
            end Show_Kind;
         begin
            if Pos (1) = "package" and then One = "" then
               raise Usage_Error with "interface package takes one package name";
            end if;
            if All_K or Only_M then
               Show_Kind ("Messages", Msg_Part);
            end if;
            if All_K or Only_S then
               Show_Kind ("Services", Srv_Part);
            end if;
            if All_K or Only_A then
               Show_Kind ("Actions", Action_Part);
            end if;
            if not Found then
               raise Command_Error with "unknown package '" & One & "'";
            end if;
         end;
      else
         raise Usage_Error with "unknown interface sub-command '" & Pos (1) & "'";
      end if;
   end Interface_Command;

end Rclada_Commands;
