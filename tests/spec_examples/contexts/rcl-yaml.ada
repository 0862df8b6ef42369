with RCL.YAML; use RCL.YAML;
