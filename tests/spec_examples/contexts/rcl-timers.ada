with RCL.Timers;
--  DECLARATIONS
procedure Tick (Node : in out Nodes.Node'Class; Timer : in out Timers.Timer;
                Elapsed : Duration) is null;
