with RCL.DDS; use RCL.DDS;
with RCL.QoS;
