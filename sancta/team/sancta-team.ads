--  Team missions over DDS: the team network (Networks), the replicated team
--  database (Replicated_Databases), distributed allocation (Allocators), team missions
--  (Missions) and the end-to-end demo (Demos).
package Sancta.Team is
end Sancta.Team;
