with RCL.Names; use RCL.Names;
