--  sancta-view: the live mission view; see Sancta.Views.Main.
with Sancta.Team.Interface_Paths;
with Sancta.Views.Main;

procedure Sancta_View is
begin
   Sancta.Team.Interface_Paths.Ensure;  --  sancta_msgs on the ROS 2 library's path
   Sancta.Views.Main;
end Sancta_View;
