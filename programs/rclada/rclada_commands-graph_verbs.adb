--  rclada topic type | find | bw | delay and service type | find, with the
--  ros2 command's output.
separate (Rclada_Commands)
procedure Graph_Verbs (Verb : String; Args : Arguments) is

   use type RCL.Clocks.Nanoseconds;

   Pos : constant Arguments := Positional (Args);
   Sub : constant String := Pos (1);

   procedure Need (What : String) is
   begin
      if Natural (Pos.Length) /= 2 then
         raise Usage_Error with Verb & " " & Sub & " takes " & What;
      end if;
   end Need;

   function Listed (All_Names : Graph.Name_And_Types_Array) return Boolean is
      Found : Boolean := False;
   begin
      if Sub = "type" then
         for N of All_Names loop
            if To_String (N.Name) = Fully_Qualified (Pos (2)) then
               Put_Lines (Ada.Strings.Fixed.Translate
                            (To_String (N.Types),
                             Ada.Strings.Maps.To_Mapping (",", [1 => LF])));
               Found := True;
            end if;
         end loop;
      else
         for N of All_Names loop
            declare
               Types : constant String := ", " & To_String (N.Types) & ",";
            begin
               if Ada.Strings.Fixed.Index (Types, ", " & Pos (2) & ",") > 0 then
                  Put_Line (To_String (N.Name));
                  Found := True;
               end if;
            end;
         end loop;
      end if;
      return Found;
   end Listed;

   --  Statistics over a window of samples, printed every second.
   procedure Watch (Topic : String; Bandwidth : Boolean) is
      Type_Name : constant String := Topic_Type (Topic, Args);
      Support   : constant ROSIDL.Typesupport.Message_Support := Message_Support (Type_Name);
      Window    : constant Positive :=
        Positive (Number_Option (Args, "--window", "100", 1.0, 1.0e6));
      Values    : array (1 .. Window) of Long_Float := [others => 0.0];
      Count     : Natural := 0;
      Head      : Natural := 0;
      Node      : RCL.Nodes.Node := Tool_Node;

      Arrived   : array (1 .. Window) of Ada.Real_Time.Time;

      function Fmt (X : Long_Float; Aft : Natural) return String is
         S : String (1 .. 40);
      begin
         if Aft = 0 then
            return Ada.Strings.Fixed.Trim (Long_Long_Integer (X)'Image, Ada.Strings.Left);
         end if;
         Ada.Float_Text_IO.Put (S, Float (X), Aft => Aft, Exp => 0);
         return Ada.Strings.Fixed.Trim (S, Ada.Strings.Both);
      end Fmt;

      procedure On_Data
        (Node : in out RCL.Nodes.Node'Class;
         Data : RCL.DDS.Byte_Array;
         Info : ROSIDL.Message_Info)
      is
         pragma Unreferenced (Node, Info);
         V : Long_Float;
      begin
         if Bandwidth then
            V := Long_Float (Data'Length);
         else
            declare
               Msg   : constant ROSIDL.Dynamic.Message := ROSIDL.CDR.Decode (Support, Data);
               Stamp : constant RCL.Clocks.Nanoseconds :=
                 RCL.Clocks.Nanoseconds (Msg ("header")("stamp")("sec").As_Int32.Element.all)
                 * 1_000_000_000
                 + RCL.Clocks.Nanoseconds
                   (Msg ("header")("stamp")("nanosec").As_UInt32.Element.all);
            begin
               V := Long_Float (RCL.Clocks.To_Duration (RCL.Clocks.Now - Stamp));
            end;
         end if;
         Head := Head mod Window + 1;
         Values (Head) := V;
         Arrived (Head) := Ada.Real_Time.Clock;
         Count := Natural'Min (Count + 1, Window);
      exception
         when ROSIDL.Field_Error =>
            raise Command_Error with "msg does not have header";
      end On_Data;

      procedure Report
        (Node    : in out RCL.Nodes.Node'Class;
         Timer   : in out RCL.Timers.Timer;
         Elapsed : Duration)
      is
         pragma Unreferenced (Node, Timer, Elapsed);
         use Ada.Numerics.Long_Elementary_Functions;
         Sum, Sum2 : Long_Float := 0.0;
         Lo        : Long_Float := Long_Float'Last;
         Hi        : Long_Float := Long_Float'First;
      begin
         if Count = 0 then
            return;
         end if;
         for I in 1 .. Count loop
            Sum := Sum + Values (I);
            Sum2 := Sum2 + Values (I) ** 2;
            Lo := Long_Float'Min (Lo, Values (I));
            Hi := Long_Float'Max (Hi, Values (I));
         end loop;
         declare
            Mean : constant Long_Float := Sum / Long_Float (Count);
            Oldest : constant Positive := (if Count < Window then 1 else Head mod Window + 1);
            Span   : constant Long_Float := Long_Float'Max
              (0.001, Long_Float (Ada.Real_Time.To_Duration
                                    (Ada.Real_Time.Clock - Arrived (Oldest))));
         begin
            if Bandwidth then
               Put_Line (Fmt (Sum / Span, 0) & " B/s from" & Count'Image & " messages");
               Put_Line (Ada.Characters.Latin_1.HT & "Message size mean: " & Fmt (Mean, 0)
                         & " B min: " & Fmt (Lo, 0) & " B max: " & Fmt (Hi, 0) & " B");
            else
               Put_Line ("average delay: " & Fmt (Mean, 3));
               Put_Line (Ada.Characters.Latin_1.HT & "min: " & Fmt (Lo, 3) & "s max: "
                         & Fmt (Hi, 3) & "s std dev: "
                         & Fmt (Sqrt (Long_Float'Max (0.0, Sum2 / Long_Float (Count) - Mean ** 2)),
                                5)
                         & "s window:" & Count'Image);
            end if;
            Flush;
         end;
      exception
         when Ada.IO_Exceptions.Device_Error =>
            Output_Closed;
      end Report;
   begin
      if Bandwidth then
         Put_Line ("Subscribed to [" & Topic & "]");
         Flush;
      end if;
      Node.Subscribe_Raw (ROSIDL.Typesupport.DDS_Type_Name (Support), Topic, On_Data'Access);
      Node.Timer_Add (1.0, Report'Access);
      Node.Spin;
   end Watch;

begin
   if Verb = "topic" and then Sub in "bw" | "delay" then
      Check_Options (Args, "--window --spin-time");
      Need ("a topic name");
      Watch (Checked_Name (Pos (2)), Bandwidth => Sub = "bw");
      return;
   end if;
   Check_Options (Args, "--spin-time");
   Need (if Sub = "type" then "a name" else "a type");
   Discover (Args);
   if not Listed (if Verb = "topic" then Graph.Topic_Names_And_Types
                  else Graph.Service_Names_And_Types)
     and then Sub = "type"
   then
      raise Command_Error with "Unknown " & Verb & " '" & Fully_Qualified (Pos (2)) & "'";
   end if;
end Graph_Verbs;
