with RCL.Lifecycle; use RCL.Lifecycle;
--  DECLARATIONS
Support : Message_Support;
