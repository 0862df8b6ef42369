with RCL.DDS;
with RCL.Nodes; use RCL.Nodes;
--  DECLARATIONS
procedure Callback (Node : in out Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
                    Info : ROSIDL.Message_Info) is null;
procedure On_Scan (Node : in out Nodes.Node'Class; Msg : in out ROSIDL.Dynamic.Message;
                   Info : ROSIDL.Message_Info) is null;
Scan_Support : Message_Support;
procedure Ignore (Node : in out Nodes.Node'Class; Data : RCL.DDS.Byte_Array;
                  Info : ROSIDL.Message_Info) is null;
