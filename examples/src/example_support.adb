with RCL.Logging;

package body Example_Support is

   package CL renames Ada.Command_Line;

   function Argument (N : Positive; Default : String) return String is
   begin
      for I in 1 .. Integer'Min (N, CL.Argument_Count) loop
         if CL.Argument (I) = "--ros-args" then
            return Default;
         end if;
      end loop;
      return (if N <= CL.Argument_Count then CL.Argument (N) else Default);
   end Argument;

   procedure Fail
     (E      : Ada.Exceptions.Exception_Occurrence;
      Status : Ada.Command_Line.Exit_Status := 2) is
   begin
      RCL.Logging.Error (Ada.Exceptions.Exception_Message (E));
      CL.Set_Exit_Status (Status);
   end Fail;

end Example_Support;
