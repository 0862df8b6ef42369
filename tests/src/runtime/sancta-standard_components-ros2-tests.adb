with Ada.Exceptions;
with Ada.Numerics;
with AUnit.Assertions;
with ROSIDL.CDR;
with ROSIDL.Typesupport;
with Sancta.Geometry;
with Sancta.Runtime.Values;
with Suite_Support; use Suite_Support;

package body Sancta.Standard_Components.ROS2.Tests is

   use AUnit.Assertions;
   use ROSIDL.Dynamic;
   use Sancta.Runtime;
   use type Geometry.Real;

   function Empty (Pkg, Name : String) return Message is
     (Init (ROSIDL.Typesupport.Get_Message_Support (Pkg, Name)));

   function Near (A, B : Geometry.Real) return Boolean is (abs (A - B) < 1.0E-9);

   procedure Poses (Unused : in out Fixture) is
      P : constant Geometry.Pose := (X => 1.5, Y => -2.0, Yaw => 3.0 * Ada.Numerics.Pi / 4.0);
      V : constant Values.Pose_Value := (Data => P);

      procedure Round_Trip (Name : String) is
         M    : constant Message := To_Message (V, Empty ("geometry_msgs", Name), "map");
         Wire : constant Message := ROSIDL.CDR.Decode (Support (M), ROSIDL.CDR.Encode (M));
         Back : constant Values.Value'Class := To_Value (Wire);
      begin
         Assert (Back in Values.Pose_Value, Name & " converts to a pose");
         Assert (Near (Values.Pose_Value (Back).Data.X, P.X)
                 and then Near (Values.Pose_Value (Back).Data.Y, P.Y)
                 and then Near (Values.Pose_Value (Back).Data.Yaw, P.Yaw),
                 Name & " round trip: " & Back.Image);
      end Round_Trip;

   begin
      Round_Trip ("Pose2D");
      Round_Trip ("Pose");
      Round_Trip ("PoseStamped");
      declare
         M : constant Message := To_Message (V, Empty ("nav_msgs", "Odometry"), "odom");
      begin
         Assert (M ("header")("frame_id").Get_String = "odom", "frame_id");
         Assert (abs (Long_Float (M ("pose")("pose")("orientation")("z").As_Float64.Element.all)
                      - 0.923879532511287) < 1.0E-9, "quaternion z = sin (yaw / 2)");
         Assert (Near (Values.Pose_Value (To_Value (M)).Data.Yaw, P.Yaw), "odometry yaw");
      end;
   end Poses;

   procedure Scalars (Unused : in out Fixture) is
      R : constant Values.Value'Class :=
        To_Value (To_Message (Values.Integer_Value'(Data => 7), Empty ("std_msgs", "Float64")));
      I : constant Values.Value'Class :=
        To_Value (To_Message (Values.Integer_Value'(Data => -9), Empty ("std_msgs", "Int16")));
      B : constant Values.Value'Class :=
        To_Value (To_Message (Values.Boolean_Value'(Data => True), Empty ("std_msgs", "Bool")));
      S : constant Values.Value'Class :=
        To_Value (To_Message (Values.Real_Value'(Data => 0.5), Empty ("std_msgs", "String")));
   begin
      Assert (R in Values.Real_Value and then Values.Real_Value (R).Data = 7.0, R.Image);
      Assert (I in Values.Integer_Value and then Values.Integer_Value (I).Data = -9, I.Image);
      Assert (B in Values.Boolean_Value and then Values.Boolean_Value (B).Data, B.Image);
      Assert (S in Values.String_Value and then S.Image = "0.5", S.Image);
   end Scalars;

   procedure Other_Messages (Unused : in out Fixture) is
      M : constant Message := Empty ("geometry_msgs", "Twist");
      V : constant Values.Value'Class := To_Value (M);
   begin
      M ("linear")("x").As_Float64.Element.all := 0.25;
      Assert (V in Message_Value, "no conversion: a message value");
      Assert (V.Type_Name = "ros2:geometry_msgs/msg/Twist", V.Type_Name);
      Assert (Values.Is_Known_Type ("ros2:geometry_msgs/msg/Twist"), "ros2: family known");
      Assert (not Values.Is_Known_Type ("ros2:geometry_msgs/msg/Twits"), "unknown message");
      Assert (To_Message (Message_Value'(Message => M), Empty ("geometry_msgs", "Twist")) = M,
              "a message value of the right type passes as is");
      begin
         declare
            Unused : constant Message :=
              To_Message (Values.Boolean_Value'(Data => True),
                          Empty ("geometry_msgs", "Pose"));
         begin
            Assert (False, "a boolean is no pose");
         end;
      exception
         when E : Type_Error =>
            Assert (Ada.Exceptions.Exception_Message (E)
                    = "cannot convert a value of type types.boolean to geometry_msgs/msg/Pose",
                    Ada.Exceptions.Exception_Message (E));
      end;
   end Other_Messages;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("ros2 bridges: poses to and from messages", Poses'Access));
      Result.Add_Test (Caller.Create ("ros2 bridges: scalar messages", Scalars'Access));
      Result.Add_Test (Caller.Create ("ros2 bridges: other messages, type errors",
                                      Other_Messages'Access));
      return Result;
   end Suite;

end Sancta.Standard_Components.ROS2.Tests;
