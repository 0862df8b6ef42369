--  rclada bag record | info | play, as "ros2 bag" with its MCAP storage (info
--  and play also read its sqlite3 storage, .db3)
--  (RCL.Bags: rosbag2's directory layout and metadata.yaml).
with Ada.Calendar.Formatting;
with Ada.Characters.Handling;
with Ada.Command_Line;
with Ada.Containers;
with Ada.Streams;
with Interfaces;
with RCL.Bags.Recorders;
with RCL.MCAP;
with ROSIDL.Parser;

separate (Rclada_Commands)
procedure Bag_Command (Args : Arguments) is
   use type Interfaces.Unsigned_64;
   use type Ada.Containers.Count_Type;
   use type Ada.Streams.Stream_Element_Offset;
   use type RCL.MCAP.Compression_Kind;
   use type RCL.Bags.Bag_Compression;

   --  Options: "--name value" pairs, flags, and the rest positional.
   Valued : constant String :=
     " -o --output --duration -b --max-bag-size -d --max-bag-duration --compression"
     & " --compression-mode --compression-format -r --rate --clock --delay"
     & " --discovery-period ";
   Flags  : constant String :=
     " -a --all --include-hidden-topics -l --loop --recover ";

   Positionals : Arguments;
   Play_Topics : Arguments;

   function Is_Valued (A : String) return Boolean is
     (Ada.Strings.Fixed.Index (Valued, " " & A & " ") /= 0);

   function Starts_Number (A : String) return Boolean is
     (A'Length > 0 and then A (A'First) in '0' .. '9' | '.');

   function Value_Of (Short, Long, Default : String) return String is
   begin
      for I in Args.First_Index .. Args.Last_Index loop
         if Args (I) = Short or else Args (I) = Long then
            if I = Args.Last_Index or else
              (Long = "--clock" and then not Starts_Number (Args (I + 1)))
            then
               if Long = "--clock" then
                  return "40";  --  rosbag2's default /clock rate with --clock alone
               end if;
               raise Usage_Error with Long & " needs a value";
            end if;
            return Args (I + 1);
         end if;
      end loop;
      return Default;
   end Value_Of;

   function Number (Short, Long, Default : String; Low, High : Long_Float) return Long_Float is
     (Long_Float_Number (Long, Value_Of (Short, Long, Default), Low, High));

   function Flag (Short, Long : String) return Boolean is
     (for some A of Args => A = Short or else A = Long);

   procedure Split_Arguments is
      Skip     : Boolean := False;
      In_Topics : Boolean := False;
   begin
      for I in Args.First_Index .. Args.Last_Index loop
         declare
            A : constant String := Args (I);
         begin
            if Skip then
               Skip := False;
            elsif A = "--topics" then
               In_Topics := True;
            elsif A = "--clock" then
               In_Topics := False;
               Skip := I < Args.Last_Index and then Starts_Number (Args (I + 1));
            elsif A'Length > 1 and then A (A'First) = '-' then
               In_Topics := False;
               if Is_Valued (A) then
                  Skip := True;
               elsif Ada.Strings.Fixed.Index (Flags, " " & A & " ") = 0 then
                  raise Usage_Error with "unknown option " & A;
               end if;
            elsif In_Topics then
               Play_Topics.Append (A);
            else
               Positionals.Append (A);
            end if;
         end;
      end loop;
   end Split_Arguments;

   ----------------
   -- Record_Bag --
   ----------------

   procedure Record_Bag is
      use Ada.Calendar;
      Default_Name : constant String :=
        "rosbag2_" & Formatting.Image (Clock) (1 .. 10) & "-"
        & Formatting.Image (Clock) (12 .. 19);
      Output   : constant String :=
        Value_Of ("-o", "--output",
                  Ada.Strings.Fixed.Translate
                    (Default_Name, Ada.Strings.Maps.To_Mapping (":-", "__")));
      Stop_After : constant Long_Float :=
        Number ("--duration", "--duration", "0", 0.0, 1.0e9);
      Max_Bytes : constant Long_Float :=
        Number ("-b", "--max-bag-size", "0", 0.0, 1.0e15);
      Max_Span : constant Long_Float :=
        Number ("-d", "--max-bag-duration", "0", 0.0, 1.0e9);
      Period   : constant Long_Float :=
        Number ("--discovery-period", "--discovery-period", "0.5", 0.01, 60.0);
      Kind     : RCL.MCAP.Compression_Kind;
      Mode_Text : constant String :=
        Ada.Characters.Handling.To_Lower (Value_Of ("--compression-mode", "--compression-mode",
                                                    "none"));
      Format_Text : constant String :=
        Value_Of ("--compression-format", "--compression-format", "zstd");
      Mode     : RCL.Bags.Bag_Compression;
      Topics   : RCL.Bags.Recorders.Topic_List;
      Node     : RCL.Nodes.Node := Tool_Node;
      Rec      : RCL.Bags.Recorders.Recorder;
      Deadline : constant Ada.Real_Time.Time :=
        Ada.Real_Time.Clock
        + (if Stop_After > 0.0 then Ada.Real_Time.To_Time_Span (Duration (Stop_After))
           else Ada.Real_Time.To_Time_Span (1.0e6));
      Next_Discovery : Ada.Real_Time.Time := Ada.Real_Time.Clock;
   begin
      if Mode_Text = "file" then
         Mode := RCL.Bags.File_Compression;
      elsif Mode_Text = "message" then
         Mode := RCL.Bags.Message_Compression;
      elsif Mode_Text = "none" then
         Mode := RCL.Bags.No_Compression;
      else
         raise Usage_Error with "--compression-mode: '" & RCL.Names.Shortened (Mode_Text)
           & "': expected file, message or none";
      end if;
      if Format_Text /= "zstd" then
         raise Usage_Error with "--compression-format: '" & RCL.Names.Shortened (Format_Text)
           & "': only zstd";
      end if;
      begin
         --  MCAP's chunks: zstd unless rosbag2's compression is asked for
         --  (compressing what is compressed gains nothing).
         Kind := RCL.MCAP.Compression_Value
           (Value_Of ("--compression", "--compression",
                      (if Mode = RCL.Bags.No_Compression then "zstd" else "none")));
      exception
         when E : RCL.MCAP.Format_Error =>
            raise Usage_Error with "--compression: " & Ada.Exceptions.Exception_Message (E);
      end;
      for I in Positionals.First_Index + 1 .. Positionals.Last_Index loop
         declare
            Name : constant String := Positionals (I);
            Full : constant String :=
              (if Name'Length > 0 and then Name (Name'First) /= '/' then "/" & Name else Name);
            --  As the recorder makes a relative name absolute.
         begin
            if RCL.Names.Topic_Problem (Full) /= "" then
               --  Was recorded as a wish no topic can fulfil: nothing, silently.
               raise Usage_Error with "bag record: " & RCL.Names.Topic_Problem (Full);
            end if;
            Topics.Append (Name);
         end;
      end loop;
      if Topics.Is_Empty and then not Flag ("-a", "--all") then
         raise Usage_Error with "bag record needs topics, or -a to record every topic";
      elsif not Topics.Is_Empty and then Flag ("-a", "--all") then
         raise Usage_Error with "bag record takes either topics or -a, not both";
      end if;
      begin
         Rec.Start (Output, Topics, Kind, Interfaces.Unsigned_64 (Max_Bytes), Duration (Max_Span),
                    Include_Hidden => Flag ("--include-hidden-topics", "--include-hidden-topics"),
                    Mode => Mode);
      exception
         when E : RCL.Bags.Bag_Error =>
            raise Command_Error with Ada.Exceptions.Exception_Message (E);
      end;
      RCL.Contexts.Install_Signal_Handlers;
      Put_Line ("Recording to '" & Output & "' ("
                & (case Mode is
                      when RCL.Bags.No_Compression => "",
                      when RCL.Bags.File_Compression => "zstd files, chunks ",
                      when RCL.Bags.Message_Compression => "zstd messages, chunks ")
                & (if Kind = RCL.MCAP.None then "none" else RCL.MCAP.Image (Kind)) & ")...");
      Flush;
      Graph.Wait_For_Discovery (0.3);
      while not RCL.Contexts.Is_Shutdown and then Ada.Real_Time.Clock < Deadline loop
         if Ada.Real_Time.Clock >= Next_Discovery then
            Rec.Discover (Node);
            Next_Discovery := Ada.Real_Time.Clock + Ada.Real_Time.To_Time_Span (Duration (Period));
         end if;
         Node.Spin (During => Duration'Min
                      (Duration (Period),
                       Ada.Real_Time.To_Duration (Deadline - Ada.Real_Time.Clock)));
      end loop;
      Rec.Stop;
      Put_Line ("Recorded" & Rec.Message_Count'Image & " messages on" & Rec.Topic_Count'Image
                & " topics into '" & Output & "'");
   end Record_Bag;

   function Extra_Argument return String is
     (if Natural (Positionals.Length) > 2
      then ", not also '" & RCL.Names.Shortened (Positionals (3)) & "'"
      else "");
   --  The first argument past the bag, for the usage error.

   procedure Warn (Reader : RCL.Bags.Bag_Reader) is
   begin
      if Reader.Warning /= "" then
         Put_Line (Standard_Error, "rclada: warning: " & Reader.Warning);
      end if;
   end Warn;

   ----------
   -- Info --
   ----------

   procedure Info_Bag is
      Reader : RCL.Bags.Bag_Reader;
   begin
      if Positionals.Length /= 2 then
         raise Usage_Error with "bag info takes one bag (directory, .mcap or .db3 file)"
           & Extra_Argument;
      end if;
      --  A signal stops a long decompression (a bag compressed whole); the
      --  reader then deletes its temporary file.
      RCL.Contexts.Install_Signal_Handlers;
      begin
         Reader.Open (Positionals (2), Recover => Flag ("--recover", "--recover"));
      exception
         when E : RCL.Bags.Bag_Error | RCL.MCAP.Format_Error =>
            raise Command_Error with Ada.Exceptions.Exception_Message (E);
      end;
      Warn (Reader);
      Put (Reader.Info);
   end Info_Bag;

   ----------
   -- Play --
   ----------

   function Type_Problem (Name : String) return String is
      --  "" when Name is a type as rosbag2 records it, "pkg/msg/Name" (or
      --  srv, action; generated names such as Fibonacci_FeedbackMessage),
      --  else what is wrong: it names the DDS type of the played topic.
      First  : constant Natural := Ada.Strings.Fixed.Index (Name, "/");
      Second : constant Natural :=
        (if First = 0 then 0 else Ada.Strings.Fixed.Index (Name (First + 1 .. Name'Last), "/"));
      Quoted : constant String := "type '" & RCL.Names.Shortened (Name) & "'";
   begin
      if Name = "" then
         return "no message type (the channel has no schema)";
      elsif Second = 0 or else Ada.Strings.Fixed.Index (Name (Second + 1 .. Name'Last), "/") /= 0
      then
         return Quoted & ": expected package/msg/Type";
      end if;
      declare
         Package_Name : String renames Name (Name'First .. First - 1);
         Kind         : String renames Name (First + 1 .. Second - 1);
         Type_Name    : String renames Name (Second + 1 .. Name'Last);
      begin
         if not ROSIDL.Parser.Is_Valid_Package_Name (Package_Name) then
            return Quoted & ": invalid package name '" & RCL.Names.Shortened (Package_Name) & "'";
         elsif Kind not in "msg" | "srv" | "action" then
            return Quoted & ": expected msg, srv or action after the package, found '"
              & RCL.Names.Shortened (Kind) & "'";
         elsif Type_Name = "" or else Type_Name (Type_Name'First) not in 'A' .. 'Z'
           or else (for some C of Type_Name => C not in 'A' .. 'Z' | 'a' .. 'z' | '0' .. '9' | '_')
         then
            return Quoted & ": invalid type name '" & RCL.Names.Shortened (Type_Name) & "'";
         end if;
      end;
      return "";
   end Type_Problem;

   procedure Play_Bag is
      use Ada.Real_Time;
      Reader : RCL.Bags.Bag_Reader;
      Rate   : constant Long_Float := Number ("-r", "--rate", "1.0", 1.0e-6, 1.0e6);
      Clock_Hz : constant Long_Float :=
        (if Flag ("--clock", "--clock") then Number ("--clock", "--clock", "40", 0.001, 1.0e4)
         else 0.0);
      Wait   : constant Long_Float := Number ("--delay", "--delay", "0.5", 0.0, 3600.0);
      Node   : RCL.Nodes.Node := Tool_Node;
      Stopped : exception;
   begin
      if Positionals.Length /= 2 then
         raise Usage_Error with "bag play takes one bag (directory, .mcap or .db3 file)"
           & Extra_Argument;
      end if;
      begin
         Reader.Open (Positionals (2));
      exception
         when E : RCL.Bags.Bag_Error | RCL.MCAP.Format_Error =>
            raise Command_Error with Ada.Exceptions.Exception_Message (E);
      end;
      Warn (Reader);
      declare
         type Publisher_Access is access RCL.Publishers.Publisher;
         type Publisher_Array is array (RCL.Bags.Topic_Index range <>) of Publisher_Access;
         Pubs       : Publisher_Array (1 .. RCL.Bags.Topic_Index'Base (Reader.Topic_Count));
         Clock_Pub  : Publisher_Access;
         Bag_Start  : constant RCL.MCAP.Time_Stamp := Reader.Start_Time;
         Wall_Start : Time;
         Clock_Period : constant Time_Span :=
           (if Clock_Hz > 0.0 then To_Time_Span (Duration (1.0 / Clock_Hz)) else Time_Span_Last);
         Next_Clock : Time;
         Played     : Natural := 0;
         Too_Short  : Natural := 0;
         First_Short : Unbounded_String;
         --  Messages shorter than a CDR header (not played), where the first is.

         function Bag_Time_At (T : Time) return RCL.MCAP.Time_Stamp is
           (Bag_Start + RCL.MCAP.Time_Stamp
              (Long_Float'Max (0.0, Long_Float (To_Duration (T - Wall_Start))) * Rate * 1.0e9));

         procedure Publish_Clock (Stamp : RCL.MCAP.Time_Stamp) is
            use Interfaces;
            Sec  : constant Unsigned_32 := Unsigned_32 (Stamp / 1_000_000_000);
            Nsec : constant Unsigned_32 := Unsigned_32 (Stamp mod 1_000_000_000);
            Data : RCL.DDS.Byte_Array (1 .. 12) := [2 => 1, others => 0];
         begin
            for I in 0 .. 3 loop
               Data (5 + Ada.Streams.Stream_Element_Offset (I)) :=
                 Ada.Streams.Stream_Element (Shift_Right (Sec, 8 * I) and 16#FF#);
               Data (9 + Ada.Streams.Stream_Element_Offset (I)) :=
                 Ada.Streams.Stream_Element (Shift_Right (Nsec, 8 * I) and 16#FF#);
            end loop;
            Clock_Pub.Publish_Raw (Data);
         end Publish_Clock;

         procedure Each (Topic : RCL.Bags.Topic_Index; Receive_Time : RCL.MCAP.Time_Stamp;
                         Data : RCL.MCAP.Byte_Array) is
            Offset : constant Long_Float :=
              (if Receive_Time > Bag_Start then Long_Float (Receive_Time - Bag_Start) / 1.0e9
               else 0.0);
            Longest_Wait : constant Long_Float := 1.0e9;
            --  Seconds (about 31 years): a later message (a log time near 2**64,
            --  or a long bag at --rate 1e-6) is due "never" (a signal ends the
            --  wait) instead of overflowing Duration.
            Due    : constant Time :=
              Wall_Start + To_Time_Span (Duration (Long_Float'Min (Offset / Rate, Longest_Wait)));

            procedure Wait_Until (T : Time) is
            --  In slices, so that a signal (shutdown) stops a long wait: a bag
            --  whose log times jump far ahead would otherwise wait for years.
            begin
               while Clock < T and then not RCL.Contexts.Is_Shutdown loop
                  declare
                     Slice_End : constant Time := Clock + Milliseconds (100);
                  begin
                     delay until (if T < Slice_End then T else Slice_End);
                  end;
               end loop;
            end Wait_Until;
         begin
            loop
               exit when RCL.Contexts.Is_Shutdown;
               if Clock_Pub /= null and then Next_Clock <= Due then
                  Wait_Until (Next_Clock);
                  exit when RCL.Contexts.Is_Shutdown;
                  Publish_Clock (Bag_Time_At (Next_Clock));
                  Next_Clock := Next_Clock + Clock_Period;
               else
                  Wait_Until (Due);
                  exit;
               end if;
            end loop;
            if RCL.Contexts.Is_Shutdown then
               raise Stopped;
            end if;
            if Topic in Pubs'Range and then Pubs (Topic) /= null then
               if Data'Length >= 4 then
                  Pubs (Topic).Publish_Raw (Data);
                  Played := Played + 1;
               else
                  Too_Short := Too_Short + 1;
                  if Too_Short = 1 then
                     First_Short := To_Unbounded_String
                       (Reader.Message_Place & " (topic "
                        & RCL.Names.Shortened (Reader.Topic_Name (Topic)) & "):"
                        & Data'Length'Image & " bytes");
                  end if;
               end if;
            end if;
         exception
            when RCL.ROS_Exception =>
               --  A signal between a shutdown check above and a publish.
               if RCL.Contexts.Is_Shutdown then
                  raise Stopped;
               end if;
               raise;
         end Each;
      begin
         for Name of Play_Topics loop
            if not (for some T in Pubs'Range => Reader.Topic_Name (T) = Name) then
               raise Command_Error with "--topics: the bag has no topic '"
                 & RCL.Names.Shortened (Name) & "'"
                 & (if (for some T in Pubs'Range => Reader.Topic_Name (T) = "/" & Name)
                    then " (its topics are fully qualified: '/" & RCL.Names.Shortened (Name)
                      & "')"
                    else "");
            end if;
         end loop;
         --  Every topic to play is checked before any is: a bag whose topic
         --  name or type is unusable is refused, naming its record.
         for T in Pubs'Range loop
            declare
               Name : constant String := Reader.Topic_Name (T);
               Kind : constant String := Reader.Topic_Type (T);
            begin
               if Play_Topics.Is_Empty or else Play_Topics.Contains (Name) then
                  if Type_Problem (Kind) /= "" then
                     raise Command_Error with Reader.Type_Place (T) & ": topic '"
                       & RCL.Names.Shortened (Name) & "': " & Type_Problem (Kind);
                  elsif RCL.Bags.Offered_QoS_Problem (Reader.Topic_QoS (T)) /= "" then
                     raise Command_Error with Reader.Topic_Place (T)
                       & ": offered_qos_profiles: "
                       & RCL.Bags.Offered_QoS_Problem (Reader.Topic_QoS (T));
                  end if;
                  begin
                     Pubs (T) := new RCL.Publishers.Publisher'
                       (Node.Publish_Raw (Graph.Mangle_Type (Kind), Name,
                                          RCL.Bags.Playback_QoS (Reader.Topic_QoS (T))));
                  exception
                     when E : RCL.Names.Name_Error =>
                        raise Command_Error with Reader.Topic_Place (T) & ": "
                          & Ada.Exceptions.Exception_Message (E);
                  end;
               end if;
            end;
         end loop;
         if Clock_Hz > 0.0 then
            Clock_Pub := new RCL.Publishers.Publisher'
              (Node.Publish_Raw ("rosgraph_msgs::msg::dds_::Clock_", "/clock", RCL.QoS.Clock));
         end if;
         RCL.Contexts.Install_Signal_Handlers;
         delay Duration (Wait);  --  Discovery: let subscribers match.
         loop
            Wall_Start := Clock;
            Next_Clock := Wall_Start;
            begin
               Reader.Iterate (Each'Access);
            exception
               when Stopped => null;
            end;
            exit when RCL.Contexts.Is_Shutdown or else not Flag ("-l", "--loop");
         end loop;
         Put_Line ("Played" & Played'Image & " messages");
         delay 0.2;  --  Let reliable data reach late readers before the writers go.
         if Too_Short > 0 then
            --  Written here, not raised: an exception message is cut at 200
            --  characters.
            Put_Line (Standard_Error, "rclada: "
                      & Ada.Strings.Fixed.Trim (Too_Short'Image, Ada.Strings.Left)
                      & " message(s) not played, shorter than a CDR header (4 bytes); the"
                      & " first: " & To_String (First_Short));
            Ada.Command_Line.Set_Exit_Status (1);
         end if;
      end;
   end Play_Bag;

begin
   Split_Arguments;
   if Positionals.Is_Empty then
      raise Usage_Error with "missing sub-command (record, info, play)";
   elsif Positionals (1) = "record" then
      Record_Bag;
   elsif Positionals (1) = "info" then
      Info_Bag;
   elsif Positionals (1) = "play" then
      Play_Bag;
   else
      raise Usage_Error with "unknown sub-command '" & Positionals (1)
        & "' (record, info, play)";
   end if;
exception
   when E : RCL.MCAP.Format_Error | RCL.Bags.Bag_Error =>
      raise Command_Error with Ada.Exceptions.Exception_Message (E);
end Bag_Command;
