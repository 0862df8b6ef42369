--  Robot lists of sancta-sim: one robot per line (in a file) or per
--  --robot option, as
--
--     NAME X Y YAW [KEY=VALUE ...]      # comment
--
--  NAME: a ROS 2 namespace component (letters, digits, '_', not starting
--  with a digit); X, Y in metres, YAW in radians. Keys (defaults are those
--  of Simulators.Robot_Config):
--     radius, max_linear, max_angular         the base (m, m/s, rad/s)
--     beams, fov (degrees), range, laser_noise (m), laser_rate (Hz, 0: none)
--     odom_rate (Hz), odom_scale (relative distance error), odom_bias
--     (heading drift, rad/s), odom_noise (m per metre travelled),
--     odom_angular_scale (relative turn error), odom_angular_noise (rad
--     per radian turned)
--     gps (on | off), gps_rate (Hz), gps_std (m)
--
--     L : Robot_List;
--     Parse_Line ("robot1 1.0 2.0 0.0 beams=180 gps=on", "--robot", 1, L);
--     Load ("robots.txt", L);
with Ada.Containers.Indefinite_Vectors;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Simulation.Simulators;

package Sancta.Simulation.Robot_Lists is

   type Robot_Entry is record
      Name   : Ada.Strings.Unbounded.Unbounded_String;
      Start  : Geometry.Pose;
      Config : Simulators.Robot_Config;
   end record;

   package Entry_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Robot_Entry);
   subtype Robot_List is Entry_Vectors.Vector;

   List_Error : exception;
   --  Message "WHERE:LINE:COLUMN: what was expected, what was found".

   function Is_Valid_Name (Name : String) return Boolean;
   --  A ROS 2 name token: [A-Za-z_][A-Za-z0-9_]*.

   procedure Parse_Line
     (Line   : String;
      Where  : String;
      Number : Positive;
      List   : in out Robot_List;
      Base   : Simulators.Robot_Config := Simulators.Default_Robot);
   --  Appends the robot of Line (nothing for a blank or comment line).
   --  Raises List_Error (positioned at Where:Number:column) for a bad field,
   --  an unknown key, an invalid configuration or a name already in List.

   procedure Load (File_Name : String; List : in out Robot_List);
   --  Parse_Line on every line of the file; List_Error when it cannot be
   --  read.

   function Find (List : Robot_List; Name : String) return Natural;
   --  The index of the robot named Name, 0 when none.

end Sancta.Simulation.Robot_Lists;
