with Ada.Numerics.Generic_Elementary_Functions;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Runtime.Clocks;

package body Sancta.Standard_Components.Pose_Chain is

   use Ada.Strings.Unbounded;
   use Sancta.Geometry;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;

   package Math is new Ada.Numerics.Generic_Elementary_Functions (Real);
   use Math;

   --  odometry --

   type Odometry is new Component with record
      Current : Pose;
      Period  : Ada.Real_Time.Time_Span;
      Started : Boolean := False;
   end record;

   overriding procedure Start (This : in out Odometry);
   overriding procedure Run (This : in out Odometry; Next : in out Clocks.Time);

   overriding procedure Start (This : in out Odometry) is
   begin
      This.Current := (X => Real (This.Option_Real ("x")), Y => Real (This.Option_Real ("y")),
                       Yaw => Real (This.Option_Real ("yaw")));
      This.Period := This.Option_Duration ("period");
   end Start;

   function Speed (This : Odometry'Class; Data : String) return Real is
     (if This.Has_Value (Data) then Real (Values.Real_Value (This.Input (Data)).Data)
      else Real (This.Option_Real (Data)));

   overriding procedure Run (This : in out Odometry; Next : in out Clocks.Time) is
      Dt : constant Real := Real (Ada.Real_Time.To_Duration (This.Period));
      V  : constant Real := Speed (This, "v");
      W  : constant Real := Speed (This, "w");
   begin
      if This.Started then
         --  Exact integration of a unicycle over Dt (midpoint heading).
         This.Current :=
           (X   => This.Current.X + V * Dt * Cos (This.Current.Yaw + W * Dt / 2.0),
            Y   => This.Current.Y + V * Dt * Sin (This.Current.Yaw + W * Dt / 2.0),
            Yaw => Normalize_Angle (This.Current.Yaw + W * Dt));
      end if;
      This.Started := True;
      This.Output ("pose", Values.Pose_Value'(Data => This.Current));
      Next := Next + This.Period;
   end Run;

   function Create_Odometry is new Factory.Create_Component (Odometry);

   --  transform --

   type Transform is new Base_Component with null record;

   overriding procedure Start (This : in out Transform);
   overriding procedure On_Input
     (This : in out Transform; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Transform) is
   begin
      This.Subscribe ("frame");
      This.Subscribe ("local");
   end Start;

   overriding procedure On_Input
     (This : in out Transform; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data, Item);
   begin
      if This.Has_Value ("frame") and then This.Has_Value ("local") then
         This.Output ("world", Values.Pose_Value'
                        (Data => Compose (Values.Pose_Value (This.Input ("frame")).Data,
                                          Values.Pose_Value (This.Input ("local")).Data)));
      end if;
   end On_Input;

   function Create_Transform is new Factory.Create_Component (Transform);

begin
   Factory.Register
     ((Name       => To_Unbounded_String ("transform"),
       Doc        => To_Unbounded_String ("a pose in robot coordinates into world coordinates"),
       Ports      => Port_Vectors.Empty_Vector
                       & In_Port ("frame", "types.pose", Doc => "the robot's pose in the world")
                       & In_Port ("local", "types.pose", Doc => "a pose relative to the robot")
                       & Out_Port ("world", "types.pose"),
       Options    => Option_Vectors.Empty_Vector,
       Any_Inputs => False,
       Refine     => null,
       others     => <>),
      Create_Transform'Access);
   Factory.Register
     ((Name       => To_Unbounded_String ("odometry"),
       Doc        => To_Unbounded_String ("dead-reckoning pose source"),
       Ports      => Port_Vectors.Empty_Vector
                       & In_Port ("v", "types.real", Optional => True)
                       & In_Port ("w", "types.real", Optional => True)
                       & Out_Port ("pose", "types.pose"),
       Options    => Option_Vectors.Empty_Vector
                       & Make_Option ("period", Duration_Option, "0.1")
                       & Make_Option ("x", Real_Option, "0.0")
                       & Make_Option ("y", Real_Option, "0.0")
                       & Make_Option ("yaw", Real_Option, "0.0")
                       & Make_Option ("v", Real_Option, "0.0")
                       & Make_Option ("w", Real_Option, "0.0"),
       Any_Inputs => False,
       Refine     => null,
       others     => <>),
      Create_Odometry'Access);
end Sancta.Standard_Components.Pose_Chain;
