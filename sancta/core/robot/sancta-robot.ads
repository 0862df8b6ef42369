--  Robot-side algorithms, free of any middleware: sensor records that map
--  one to one onto the ROS 2 messages, go-to-goal control with laser
--  obstacle avoidance, task execution, occupancy-grid mapping, scan
--  matching, heading alignment, GPS fusion and path costs on grids.
--  The SANCTA components wrap these packages.
package Sancta.Robot
  with Pure
is
end Sancta.Robot;
