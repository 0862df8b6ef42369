with RCL.QoS;
with RCL.Publishers;
--  DECLARATIONS
Support : Message_Support;
