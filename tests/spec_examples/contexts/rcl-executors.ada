with RCL.Executors.Sequential;
with RCL.Executors;
with RCL.DDS;
--  DECLARATIONS
Node_1, Node_2 : Nodes.Node;
