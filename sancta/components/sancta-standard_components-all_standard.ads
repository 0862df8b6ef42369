--  "with" this package in a program to register every standard component
--  with the factory. Units of a static library are only elaborated when
--  some unit of the program depends on them, and a component registers
--  itself at elaboration: without this "with", the factory would not know
--  the standard components.
pragma Warnings (Off, "unit * is not referenced");
with Sancta.Standard_Components.GUI_Relay;
with Sancta.Standard_Components.Localization;
with Sancta.Standard_Components.Logger;
with Sancta.Standard_Components.Navigation;
with Sancta.Standard_Components.Plumbing;
with Sancta.Standard_Components.Pose_Chain;
with Sancta.Standard_Components.ROS2;
with Sancta.Standard_Components.Sources;
with Sancta.Standard_Components.Watchdog;
with Sancta.Team.Team_Components;
pragma Warnings (On, "unit * is not referenced");

package Sancta.Standard_Components.All_Standard is
end Sancta.Standard_Components.All_Standard;
