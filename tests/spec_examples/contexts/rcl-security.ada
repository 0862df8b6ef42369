with RCL.Security;
