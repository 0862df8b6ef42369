with RCL.DDS; use RCL.DDS;
with RCL.DDS.Matching; use RCL.DDS.Matching;
