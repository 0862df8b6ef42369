with RCL.Executors.Sequential;
--  DECLARATIONS
Node_1, Node_2 : Nodes.Node;
