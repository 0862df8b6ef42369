with RCL.Rates;
--  DECLARATIONS
procedure Publish_Pose is null;
