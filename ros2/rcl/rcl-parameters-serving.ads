--  The parameter services of a node (~/get_parameters, ~/set_parameters,
--  ~/set_parameters_atomically, ~/get_parameter_types,
--  ~/describe_parameters, ~/list_parameters, as rclcpp offers them) and its
--  /parameter_events publisher.
private package RCL.Parameters.Serving is

   procedure Serve (Node : in out RCL.Nodes.Node'Class);
   --  As Parameters.Serve.

   procedure Publish_Event (Node_Name : String; Names : Text_Vectors.Vector; Is_New : Boolean);
   --  A ParameterEvent listing Names (new or changed) with their current
   --  values, when Node_Name serves its parameters.

end RCL.Parameters.Serving;
