with Ada.Exceptions;
with Ada.Numerics.Long_Elementary_Functions;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with RCL.Contexts;
with RCL.DDS;
with RCL.Names;
with RCL.Nodes;
with RCL.Publishers;
with RCL.QoS;
with ROSIDL.CDR;
with ROSIDL.Definitions;
with ROSIDL.Interfaces;
with ROSIDL.Typesupport;
with Sancta.Geometry;
with Sancta.Logging;
with Sancta.Runtime.Shutdown;
with Sancta.Runtime.Tasks;

package body Sancta.Standard_Components.ROS2 is

   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use ROSIDL.Dynamic;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;

   package Math renames Ada.Numerics.Long_Elementary_Functions;

   --  Values --

   overriding function Image (This : Message_Value) return String is
      Text   : constant String := ROSIDL.Dynamic.Image (This.Message, Truncate_Length => 16);
      Result : Unbounded_String;
      I      : Natural := Text'First;
   begin
      while I <= Text'Last loop
         if Text (I) = ASCII.LF then
            --  One line: "a: 1, b: x" (indentation dropped).
            while I < Text'Last and then Text (I + 1) = ' ' loop
               I := I + 1;
            end loop;
            if I < Text'Last then
               Append (Result, ", ");
            end if;
         else
            Append (Result, Text (I));
         end if;
         I := I + 1;
      end loop;
      return To_String (Result);
   end Image;

   overriding function Type_Name (This : Message_Value) return String is
     ("ros2:" & This.Message.Type_Name);

   function F64 (R : Field_Ref) return Long_Float is (Long_Float (R.As_Float64.Element.all));

   procedure Set_F64 (R : Field_Ref; X : Long_Float) is
   begin
      R.As_Float64.Element.all := ROSIDL.Float64 (X);
   end Set_F64;

   function Pose_Of (Position, Orientation : Field_Ref) return Geometry.Pose is
      X : constant Long_Float := F64 (Orientation ("x"));
      Y : constant Long_Float := F64 (Orientation ("y"));
      Z : constant Long_Float := F64 (Orientation ("z"));
      W : constant Long_Float := F64 (Orientation ("w"));
   begin
      return (X   => Geometry.Real (F64 (Position ("x"))),
              Y   => Geometry.Real (F64 (Position ("y"))),
              Yaw => Geometry.Real
                       (Math.Arctan (2.0 * (W * Z + X * Y), 1.0 - 2.0 * (Y * Y + Z * Z))));
   end Pose_Of;

   procedure Set_Pose (Position, Orientation : Field_Ref; P : Geometry.Pose) is
   begin
      Set_F64 (Position ("x"), Long_Float (P.X));
      Set_F64 (Position ("y"), Long_Float (P.Y));
      Set_F64 (Position ("z"), 0.0);
      Set_F64 (Orientation ("x"), 0.0);
      Set_F64 (Orientation ("y"), 0.0);
      Set_F64 (Orientation ("z"), Math.Sin (Long_Float (P.Yaw) / 2.0));
      Set_F64 (Orientation ("w"), Math.Cos (Long_Float (P.Yaw) / 2.0));
   end Set_Pose;

   function Integer_Of (Msg : Message) return Long_Long_Integer is
      Name : constant String := Msg.Type_Name;
      D    : constant Field_Ref := Msg ("data");
   begin
      return
        (if Name = "std_msgs/msg/Int8" then Long_Long_Integer (D.As_Int8.Element.all)
         elsif Name = "std_msgs/msg/Int16" then Long_Long_Integer (D.As_Int16.Element.all)
         elsif Name = "std_msgs/msg/Int32" then Long_Long_Integer (D.As_Int32.Element.all)
         elsif Name = "std_msgs/msg/Int64" then Long_Long_Integer (D.As_Int64.Element.all)
         elsif Name = "std_msgs/msg/UInt8" then Long_Long_Integer (D.As_UInt8.Element.all)
         elsif Name = "std_msgs/msg/UInt16" then Long_Long_Integer (D.As_UInt16.Element.all)
         elsif Name = "std_msgs/msg/UInt32" then Long_Long_Integer (D.As_UInt32.Element.all)
         else Long_Long_Integer (D.As_UInt64.Element.all));
      --  UInt64 values above Long_Long_Integer'Last raise Constraint_Error
      --  (reported as a failure of the component).
   end Integer_Of;

   function Is_Integer_Type (Name : String) return Boolean is
     (Name in "std_msgs/msg/Int8" | "std_msgs/msg/Int16" | "std_msgs/msg/Int32"
            | "std_msgs/msg/Int64" | "std_msgs/msg/UInt8" | "std_msgs/msg/UInt16"
            | "std_msgs/msg/UInt32" | "std_msgs/msg/UInt64");

   procedure Set_Integer (Msg : Message; Value : Long_Long_Integer) is
      Name : constant String := Msg.Type_Name;
      D    : constant Field_Ref := Msg ("data");
   begin
      if Name = "std_msgs/msg/Int8" then
         D.As_Int8.Element.all := ROSIDL.Int8 (Value);
      elsif Name = "std_msgs/msg/Int16" then
         D.As_Int16.Element.all := ROSIDL.Int16 (Value);
      elsif Name = "std_msgs/msg/Int32" then
         D.As_Int32.Element.all := ROSIDL.Int32 (Value);
      elsif Name = "std_msgs/msg/Int64" then
         D.As_Int64.Element.all := ROSIDL.Int64 (Value);
      elsif Name = "std_msgs/msg/UInt8" then
         D.As_UInt8.Element.all := ROSIDL.UInt8 (Value);
      elsif Name = "std_msgs/msg/UInt16" then
         D.As_UInt16.Element.all := ROSIDL.UInt16 (Value);
      elsif Name = "std_msgs/msg/UInt32" then
         D.As_UInt32.Element.all := ROSIDL.UInt32 (Value);
      else
         D.As_UInt64.Element.all := ROSIDL.UInt64 (Value);
      end if;
   end Set_Integer;

   function To_Value
     (Msg : ROSIDL.Dynamic.Message; Convert : Boolean := True) return Runtime.Values.Value'Class
   is
      Name : constant String := Msg.Type_Name;
   begin
      if not Convert then
         return Message_Value'(Message => Msg);
      elsif Name = "geometry_msgs/msg/Pose2D" then
         return Values.Pose_Value'
           (Data => (X   => Geometry.Real (F64 (Msg ("x"))),
                     Y   => Geometry.Real (F64 (Msg ("y"))),
                     Yaw => Geometry.Real (F64 (Msg ("theta")))));
      elsif Name = "geometry_msgs/msg/Pose" then
         return Values.Pose_Value'(Data => Pose_Of (Msg ("position"), Msg ("orientation")));
      elsif Name = "geometry_msgs/msg/PoseStamped" then
         return Values.Pose_Value'
           (Data => Pose_Of (Msg ("pose")("position"), Msg ("pose")("orientation")));
      elsif Name = "nav_msgs/msg/Odometry" then
         return Values.Pose_Value'
           (Data => Pose_Of (Msg ("pose")("pose")("position"),
                             Msg ("pose")("pose")("orientation")));
      elsif Name = "std_msgs/msg/Float64" then
         return Values.Real_Value'(Data => F64 (Msg ("data")));
      elsif Name = "std_msgs/msg/Float32" then
         return Values.Real_Value'(Data => Long_Float (Msg ("data").As_Float32.Element.all));
      elsif Is_Integer_Type (Name) then
         return Values.Integer_Value'(Data => Integer_Of (Msg));
      elsif Name = "std_msgs/msg/Bool" then
         return Values.Boolean_Value'(Data => Msg ("data").As_Bool.Element.all);
      elsif Name = "std_msgs/msg/String" then
         return Values.To_Value (Msg ("data").Get_String);
      else
         return Message_Value'(Message => Msg);
      end if;
   end To_Value;

   function To_Message
     (Item     : Runtime.Values.Value'Class;
      Type_Of  : ROSIDL.Dynamic.Message;
      Frame_Id : String := "") return ROSIDL.Dynamic.Message
   is
      Name   : constant String := Type_Of.Type_Name;
      Result : constant Message := Init (Support (Type_Of));

      procedure Fail is
      begin
         raise Type_Error with "cannot convert a value of type " & Item.Type_Name & " to "
           & Name;
      end Fail;

   begin
      if Item in Message_Value then
         if Message_Value (Item).Message.Type_Name /= Name then
            Fail;
         end if;
         return Message_Value (Item).Message;
      elsif Item in Values.Pose_Value then
         declare
            P : constant Geometry.Pose := Values.Pose_Value (Item).Data;
         begin
            if Name = "geometry_msgs/msg/Pose2D" then
               Set_F64 (Result ("x"), Long_Float (P.X));
               Set_F64 (Result ("y"), Long_Float (P.Y));
               Set_F64 (Result ("theta"), Long_Float (P.Yaw));
            elsif Name = "geometry_msgs/msg/Pose" then
               Set_Pose (Result ("position"), Result ("orientation"), P);
            elsif Name = "geometry_msgs/msg/PoseStamped" then
               Result ("header")("frame_id").Set_String (Frame_Id);
               Set_Pose (Result ("pose")("position"), Result ("pose")("orientation"), P);
            elsif Name = "nav_msgs/msg/Odometry" then
               Result ("header")("frame_id").Set_String (Frame_Id);
               Set_Pose (Result ("pose")("pose")("position"),
                         Result ("pose")("pose")("orientation"), P);
            else
               Fail;
            end if;
         end;
      elsif Item in Values.Real_Value | Values.Integer_Value
        and then Name in "std_msgs/msg/Float64" | "std_msgs/msg/Float32"
      then
         declare
            X : constant Long_Float :=
              (if Item in Values.Real_Value then Values.Real_Value (Item).Data
               else Long_Float (Values.Integer_Value (Item).Data));
         begin
            if Name = "std_msgs/msg/Float64" then
               Set_F64 (Result ("data"), X);
            else
               Result ("data").As_Float32.Element.all := ROSIDL.Float32 (X);
            end if;
         end;
      elsif Item in Values.Integer_Value and then Is_Integer_Type (Name) then
         Set_Integer (Result, Values.Integer_Value (Item).Data);
      elsif Item in Values.Boolean_Value and then Name = "std_msgs/msg/Bool" then
         Result ("data").As_Bool.Element.all := Values.Boolean_Value (Item).Data;
      elsif Name = "std_msgs/msg/String" then
         Result ("data").Set_String (Item.Image);
      else
         Fail;
      end if;
      return Result;
   end To_Message;

   --  Options --

   function Check_Message_Type (Text : String) return String is
   begin
      declare
         Unused : constant ROSIDL.Definitions.Message_Access := ROSIDL.Interfaces.Message (Text);
      begin
         return "";
      end;
   exception
      when E : ROSIDL.Unknown_Type | ROSIDL.Definition_Error =>
         return "unknown ROS 2 message type '" & Text & "' ("
           & Ada.Exceptions.Exception_Message (E) & ")";
   end Check_Message_Type;

   function Full_Topic (Text : String) return String is
     (if Text'Length > 0 and then Text (Text'First) = '/' then Text else "/" & Text);

   function Check_Topic (Text : String) return String is
      Problem : constant String := RCL.Names.Topic_Problem (Full_Topic (Text));
   begin
      return (if Problem = "" then "" else "invalid topic name '" & Text & "': " & Problem);
   end Check_Topic;

   function Check_Depth (Text : String) return String is
     (if Long_Long_Integer'Value (Text) in 1 .. 100_000 then ""
      else "expected a depth in 1 .. 100000, found '" & Text & "'");

   function Is_Message_Family (Name : String) return Boolean is
     (Check_Message_Type (Name (Name'First + 5 .. Name'Last)) = "");
   --  "ros2:pkg/msg/Type".

   function Port_Type
     (Options : String_Maps.Map; Data : String; Direction : Port_Direction) return String
   is
      Name : constant String := ROSIDL.Definitions.Full_Name
        (ROSIDL.Interfaces.Message (Options ("msg_type")).all);
   begin
      if Data /= "message" then
         return "";
      elsif Direction = Output and then Options ("convert") = "message" then
         return "ros2:" & Name;
      elsif Name in "geometry_msgs/msg/Pose2D" | "geometry_msgs/msg/Pose"
                  | "geometry_msgs/msg/PoseStamped" | "nav_msgs/msg/Odometry"
      then
         return "types.pose";
      elsif Name in "std_msgs/msg/Float64" | "std_msgs/msg/Float32" then
         return (if Direction = Output then "types.real" else "");
         --  A publisher of floats also takes integers.
      elsif Is_Integer_Type (Name) then
         return "types.integer";
      elsif Name = "std_msgs/msg/Bool" then
         return "types.boolean";
      elsif Name = "std_msgs/msg/String" then
         return (if Direction = Output then "types.string" else "");
         --  A publisher of strings takes any value (its Image).
      else
         return "ros2:" & Name;
      end if;
   end Port_Type;

   function ROS_Shut_Down return Boolean is (RCL.Contexts.Is_Shutdown);

   function Common_Options return Option_Vectors.Vector is
     (Option_Vectors.Empty_Vector
        & Make_Option ("topic", Text_Option, Required => True, Check => Check_Topic'Access)
        & Make_Option ("msg_type", Text_Option, Required => True,
                       Check => Check_Message_Type'Access)
        & Make_Option ("reliability", Choice_Option, "reliable",
                       Choices => "reliable best_effort")
        & Make_Option ("depth", Integer_Option, "10", Check => Check_Depth'Access));

   function Node_Name (This : Component'Class) return String is
     (RCL.Names.Name_Token ("sancta_" & This.Agent_Id & "_" & This.Name));

   function Profile_Of (This : Component'Class) return RCL.QoS.Profile is
     ((Depth       => Positive (Long_Long_Integer'(This.Option_Integer ("depth"))),
       Reliability => (if This.Option_Text ("reliability") = "best_effort"
                       then RCL.QoS.Best_Effort else RCL.QoS.Reliable),
       others      => <>));

   function Support_Of (This : Component'Class) return ROSIDL.Typesupport.Message_Support is
     (ROSIDL.Typesupport.To_Support (ROSIDL.Interfaces.Message (This.Option_Text ("msg_type"))));

   --  ros2_subscriber --

   type Subscriber;

   task type Spinner (Owner : not null access Subscriber) is
      entry Ready (Problem : out Unbounded_String);
   end Spinner;

   type Spinner_Access is access Spinner;

   type Subscriber is new Component with record
      Support  : ROSIDL.Typesupport.Message_Support;
      Convert  : Boolean := True;
      Stopping : Boolean := False with Atomic;
      Worker   : Spinner_Access;
   end record;

   overriding procedure Start (This : in out Subscriber);
   overriding procedure Stop (This : in out Subscriber);

   procedure Deliver (This : in out Subscriber; Data : RCL.DDS.Byte_Array) is
   begin
      This.Output ("message", To_Value (ROSIDL.CDR.Decode (This.Support, Data), This.Convert));
   exception
      when E : others =>
         This.Lock;
         This.Report_Failure ("message of " & This.Option_Text ("topic"), E);
         This.Unlock;
   end Deliver;

   task body Spinner is
      Announced : Boolean := False;
   begin
      declare
         Node : RCL.Nodes.Node := RCL.Nodes.Init (Node_Name (Owner.all));

         procedure On_Message
           (Node : in out RCL.Nodes.Node'Class;
            Data : RCL.DDS.Byte_Array;
            Info : ROSIDL.Message_Info)
         is
            pragma Unreferenced (Node, Info);
         begin
            if not Owner.Failed then
               Deliver (Owner.all, Data);
            end if;
         end On_Message;

      begin
         Node.Subscribe_Raw
           (ROSIDL.Typesupport.DDS_Type_Name (Owner.Support),
            Full_Topic (Owner.Option_Text ("topic")), On_Message'Access, Profile_Of (Owner.all));
         accept Ready (Problem : out Unbounded_String) do
            Problem := Null_Unbounded_String;
         end Ready;
         Announced := True;
         while not Owner.Stopping and then not RCL.Contexts.Is_Shutdown loop
            Node.Spin (During => 0.1);
         end loop;
      end;
   exception
      when E : others =>
         if Announced then
            raise;
            --  Reported by Sancta.Runtime.Tasks (the task is watched).
         end if;
         accept Ready (Problem : out Unbounded_String) do
            Problem := To_Unbounded_String
              (Ada.Exceptions.Exception_Name (E) & ": " & Ada.Exceptions.Exception_Message (E));
         end Ready;
   end Spinner;

   overriding procedure Start (This : in out Subscriber) is
      Problem : Unbounded_String;
   begin
      This.Support := Support_Of (This);
      This.Convert := This.Option_Text ("convert") = "auto";
      This.Worker := new Spinner (This'Unchecked_Access);
      Tasks.Watch (This.Worker'Identity, This.Agent_Id & "/" & This.Name);
      This.Worker.Ready (Problem);
      if Length (Problem) > 0 then
         raise Program_Error with "cannot subscribe to " & This.Option_Text ("topic") & ": "
           & To_String (Problem);
      end if;
      This.Log (Logging.Info, "subscribed to " & Full_Topic (This.Option_Text ("topic")) & " ("
                & This.Option_Text ("msg_type") & ")");
   end Start;

   overriding procedure Stop (This : in out Subscriber) is
   begin
      This.Stopping := True;
      if This.Worker /= null then
         Tasks.Await_Termination (This.Worker'Identity);
      end if;
   end Stop;

   function Create_Subscriber is new Factory.Create_Component (Subscriber);

   --  ros2_publisher --

   type Node_Access is access RCL.Nodes.Node;
   type Publisher_Access is access RCL.Publishers.Publisher;

   procedure Free is new Ada.Unchecked_Deallocation (RCL.Nodes.Node, Node_Access);
   procedure Free is new Ada.Unchecked_Deallocation (RCL.Publishers.Publisher, Publisher_Access);

   type Publisher is new Base_Component with record
      Prototype : Message;
      Node      : Node_Access;
      Writer    : Publisher_Access;
   end record;

   overriding procedure Start (This : in out Publisher);
   overriding procedure On_Input
     (This : in out Publisher; Data : String; Item : Values.Value'Class);
   overriding procedure Stop (This : in out Publisher);

   overriding procedure Start (This : in out Publisher) is
   begin
      This.Prototype := Init (Support_Of (This));
      This.Node := new RCL.Nodes.Node'(RCL.Nodes.Init (Node_Name (This)));
      This.Writer := new RCL.Publishers.Publisher'
        (This.Node.Publish_Raw
           (ROSIDL.Typesupport.DDS_Type_Name (Support (This.Prototype)),
            Full_Topic (This.Option_Text ("topic")), Profile_Of (This)));
      This.Subscribe ("message");
      This.Log (Logging.Info, "publishing on " & This.Writer.Topic & " ("
                & This.Option_Text ("msg_type") & ")");
   end Start;

   overriding procedure On_Input
     (This : in out Publisher; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
   begin
      This.Writer.Publish_Raw
        (ROSIDL.CDR.Encode (To_Message (Item, This.Prototype, This.Option_Text ("frame_id"))));
   end On_Input;

   overriding procedure Stop (This : in out Publisher) is
   begin
      Base_Component (This).Stop;
      Free (This.Writer);
      Free (This.Node);
   end Stop;

   function Create_Publisher is new Factory.Create_Component (Publisher);

begin
   Values.Register_Family ("ros2:", Is_Message_Family'Access);
   Shutdown.Add_Condition (ROS_Shut_Down'Access, "ROS 2 context shut down (Ctrl-C or SIGTERM)");
   Factory.Register
     ((Name       => To_Unbounded_String ("ros2_subscriber"),
       Doc        => To_Unbounded_String ("stores the messages of a ROS 2 topic"),
       Ports      => Port_Vectors.Empty_Vector & Out_Port ("message", Values.Any_Type),
       Options    => Common_Options
                       & Make_Option ("convert", Choice_Option, "auto",
                                      Choices => "auto message"),
       Any_Inputs => False,
       Refine     => Port_Type'Access,
       others     => <>),
      Create_Subscriber'Access);
   Factory.Register
     ((Name       => To_Unbounded_String ("ros2_publisher"),
       Doc        => To_Unbounded_String ("publishes its input on a ROS 2 topic"),
       Ports      => Port_Vectors.Empty_Vector & In_Port ("message", Values.Any_Type),
       Options    => Common_Options & Make_Option ("frame_id", Text_Option, ""),
       Any_Inputs => False,
       Refine     => Port_Type'Access,
       others     => <>),
      Create_Publisher'Access);
end Sancta.Standard_Components.ROS2;
