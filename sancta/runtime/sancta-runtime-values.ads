--  The values stored in databases: descendants of the abstract tagged type
--  Value. Each concrete type has a configuration type name ("types.pose")
--  so that the configuration can check connected ends before start-up.
--
--     DB.Put ("odometric_pose", Pose_Value'(Data => (1.0, 2.0, 0.0)));
--     P : constant Geometry.Pose := Pose_Value (DB.Get ("odometric_pose")).Data;
--
--  New value types may be declared anywhere; they register their type name
--  with Register_Type at elaboration so that configurations may use it.
with Ada.Strings.Unbounded;
with Sancta.Geometry;

package Sancta.Runtime.Values is

   type Value is abstract tagged null record;

   function Image (This : Value) return String is abstract;
   --  A human-readable text of the value (logs, CSV files).

   function JSON (This : Value) return String;
   --  A JSON text of the value; the default is Image as a JSON string.

   function Type_Name (This : Value) return String is abstract;
   --  The configuration type name, e.g. "types.pose".

   Any_Type : constant String := "any";
   --  The type of ports that accept any value (logger, copy, ...).

   procedure Register_Type (Name : String; Description : String);
   --  Make Name usable in configuration "type" attributes.

   type Family_Check is access function (Name : String) return Boolean;

   procedure Register_Family (Prefix : String; Check : not null Family_Check);
   --  Make every name starting with Prefix for which Check is True usable
   --  (e.g. "ros2:" followed by a ROS 2 message type).

   function Is_Known_Type (Name : String) return Boolean;
   --  Name was registered, belongs to a registered family, or is Any_Type.

   function Known_Types return String;
   --  Every registered type name, comma-separated (for diagnostics).

   function Compatible (Provided, Required : String) return Boolean is
     (Provided = Required or else Provided = Any_Type or else Required = Any_Type);
   --  Whether an output of type Provided may feed an input of Required.

   --  Standard value types --

   type Integer_Value is new Value with record
      Data : Long_Long_Integer := 0;
   end record;
   overriding function Image (This : Integer_Value) return String;
   overriding function JSON (This : Integer_Value) return String;
   overriding function Type_Name (This : Integer_Value) return String is ("types.integer");

   type Real_Value is new Value with record
      Data : Long_Float := 0.0;
   end record;
   overriding function Image (This : Real_Value) return String;
   overriding function JSON (This : Real_Value) return String;
   overriding function Type_Name (This : Real_Value) return String is ("types.real");

   type Boolean_Value is new Value with record
      Data : Boolean := False;
   end record;
   overriding function Image (This : Boolean_Value) return String;
   overriding function JSON (This : Boolean_Value) return String;
   overriding function Type_Name (This : Boolean_Value) return String is ("types.boolean");

   type String_Value is new Value with record
      Data : Ada.Strings.Unbounded.Unbounded_String;
   end record;
   overriding function Image (This : String_Value) return String;
   overriding function Type_Name (This : String_Value) return String is ("types.string");

   function To_Value (S : String) return String_Value is
     ((Data => Ada.Strings.Unbounded.To_Unbounded_String (S)));

   type Pose_Value is new Value with record
      Data : Geometry.Pose;
   end record;
   overriding function Image (This : Pose_Value) return String;
   overriding function JSON (This : Pose_Value) return String;
   overriding function Type_Name (This : Pose_Value) return String is ("types.pose");

   function Real_Image (X : Long_Float) return String;
   --  A short decimal text of X ("1.25", "-0.001", "1.0E+12").

   function JSON_String (S : String) return String;
   --  S quoted and escaped as a JSON string.

end Sancta.Runtime.Values;
