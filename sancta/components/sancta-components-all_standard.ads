--  "with" this package in a program to register every standard component
--  with the factory. Units of a static library are only elaborated when
--  some unit of the program depends on them, and a component registers
--  itself at elaboration: without this "with", the factory would not know
--  the standard components.
pragma Warnings (Off, "unit * is not referenced");
with Sancta.Components.GUI_Relay;
with Sancta.Components.Localization;
with Sancta.Components.Logger;
with Sancta.Components.Navigation;
with Sancta.Components.Plumbing;
with Sancta.Components.Pose_Chain;
with Sancta.Components.ROS2;
with Sancta.Components.Sources;
with Sancta.Components.Watchdog;
with Sancta.Team.Components;
pragma Warnings (On, "unit * is not referenced");

package Sancta.Components.All_Standard is
end Sancta.Components.All_Standard;
