--  sancta-view, the live mission view: a GtkAda window (or an off-screen
--  snapshot) showing a SANCTA team while it works, fed over DDS only by
--  the agents' GUI relays (sancta_msgs RobotState / TeamPlan), the
--  simulator's events and laser scans, and a world map.
--
--     Scenes    what is known of the team (pure data, updated by Feeds)
--     Feeds     the DDS side: subscriptions, operator actions
--     Drawing   the Cairo drawing of a scene (window and snapshot alike)
--     Windows   the GtkAda window and its controls
package Sancta.Views is
end Sancta.Views;
