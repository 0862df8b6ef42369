--  Initial values of parameters: the overrides read from parameter files
--  (YAML, "node: ros__parameters: ...") and from --ros-args -p / --params-file.
private package RCL.Parameters.Initial_Values is

   procedure Load_Arguments;
   --  As Parameters.Load_Arguments.

   procedure Load_File (Path : String);
   --  As Parameters.Load_File.

end RCL.Parameters.Initial_Values;
