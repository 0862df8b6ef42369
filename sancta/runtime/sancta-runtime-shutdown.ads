--  The process-wide shutdown request: Ctrl-C (SIGINT, when the runtime lets
--  it be attached), a watchdog with action "abort", or a command's time
--  limit ask for it; the launcher waits for it and stops the nodes.
package Sancta.Runtime.Shutdown is

   procedure Request (Reason : String; Failure : Boolean := False);
   --  The first reason is kept; Failure makes the program's exit status bad.

   function Requested return Boolean;
   function Failed return Boolean;
   function Reason return String;

   type Condition is access function return Boolean;

   procedure Add_Condition (Check : not null Condition; Reason : String);
   --  Another source of shutdown requests, polled by Wait (every 0.1 s):
   --  when Check returns True, Request (Reason) is done. The ROS 2 bridges
   --  add the ROS 2 context's shutdown (its own Ctrl-C handler).

   procedure Wait (Timeout : Duration; Done : out Boolean);
   --  Return when shutdown is requested (Done) or after Timeout.

   procedure Catch_Interrupt (Attached : out Boolean);
   --  Attach the SIGINT handler (Ctrl-C requests the shutdown). Attached is
   --  False when the Ada runtime reserves SIGINT.

   procedure Reset;
   --  For tests: forget the request.

end Sancta.Runtime.Shutdown;
