with RCL.Nodes.Typed;
with RCL.Publishers;
with ROSIDL.Static.Std_Msgs.Messages.String;
--  DECLARATIONS
procedure On_Message (Node : in out Nodes.Node'Class;
                      Msg  : ROSIDL.Static.Std_Msgs.Messages.String.Message;
                      Info : ROSIDL.Message_Info) is null;
