separate (Rclada_Commands)
procedure Param_Command (Args : Arguments) is
   pragma Unreferenced (Args);
begin
   raise Command_Error with "parameters are not available yet in this build";
end Param_Command;
