with RCL.Security.Keystores; use RCL.Security.Keystores;
