--  Reporting the end of the tasks of asynchronous components with
--  Ada.Task_Termination. The termination handler (a protected procedure)
--  only records the event; Report_Ended logs the records (section "tasks")
--  outside any protected action: an abnormal end or an unhandled exception
--  as an error naming the component, a normal end at debug level. Every
--  scheduler task calls Report_Ended after each round of calls, and nodes
--  call it when they stop.
--
--     task type Worker ...;  W : Worker_Access := new Worker;
--     Sancta.Runtime.Tasks.Watch (W'Identity, This.Name);
with Ada.Task_Identification;

package Sancta.Runtime.Tasks is

   procedure Watch (Id : Ada.Task_Identification.Task_Id; Name : String);
   --  Report the termination of task Id under Name.

   procedure Report_Ended;
   --  Log the terminations recorded since the last call.

   function Abnormal_Ends return Natural;
   --  How many watched tasks ended abnormally or by an exception so far.

   procedure Await_Termination (Id : Ada.Task_Identification.Task_Id);
   --  Returns once task Id has terminated (checked every 10 ms): how a
   --  component's Stop waits for the worker task it has told to stop.
   --  Example: This.Stopping := True; Await_Termination (This.Worker'Identity);

end Sancta.Runtime.Tasks;
