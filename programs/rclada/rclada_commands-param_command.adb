with RCL.Parameters;
with RCL.YAML;

separate (Rclada_Commands)
procedure Param_Command (Args : Arguments) is
   use RCL.Parameters;
   Pos : constant Arguments := Positional (Args);
   Timeout : constant Duration := Duration (Number_Option (Args, "--timeout", "5.0"));

   function Call (Node_Name, Service, Type_Name : String;
                  Fill : not null access procedure (Request : ROSIDL.Dynamic.Message))
                  return ROSIDL.Dynamic.Message
   is
      Support : constant ROSIDL.Typesupport.Service_Support :=
        ROSIDL.Typesupport.Get_Service_Support ("rcl_interfaces", Type_Name);
      Node    : constant RCL.Nodes.Node := Tool_Node;
      Client  : RCL.Clients.Client;
      Request : constant ROSIDL.Dynamic.Message :=
        ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support (Support));
   begin
      Client.Init (Node, Support, Node_Name & "/" & Service);
      if not Client.Wait_For_Service (Timeout) then
         raise Command_Error with "Node not found: " & Node_Name & " (no " & Service
           & " service after" & Timeout'Image & " s)";
      end if;
      Fill (Request);
      return Client.Call (Request, Timeout);
   exception
      when E : RCL.RCL_Timeout =>
         raise Command_Error with Ada.Exceptions.Exception_Message (E);
   end Call;

   function Kind_Word (K : Parameter_Type) return String is
     (case K is
         when Bool_Type | Bool_Array_Type => "Boolean",
         when Integer_Type | Integer_Array_Type => "Integer",
         when Double_Type | Double_Array_Type => "Double",
         when String_Type | String_Array_Type => "String",
         when Byte_Array_Type => "Byte",
         when Not_Set => "");

   function Sorted_Names (Node_Name : String) return Argument_Vectors.Vector is
      --  The node's parameter names (~/list_parameters), sorted.
      procedure No_Fill (Request : ROSIDL.Dynamic.Message) is null;
      Listed : constant ROSIDL.Dynamic.Message :=
        Call (Node_Name, "list_parameters", "ListParameters", No_Fill'Access);
      Names  : constant ROSIDL.Dynamic.Array_Ref := Listed ("result")("names").As_Array;
      Sorted : Argument_Vectors.Vector;
      package Sorting is new Argument_Vectors.Generic_Sorting;
   begin
      for I in 1 .. Names.Length loop
         Sorted.Append (Names.Element (I).Get_String);
      end loop;
      Sorting.Sort (Sorted);
      return Sorted;
   end Sorted_Names;

   procedure Ask_For_Named_Parameter (Request : ROSIDL.Dynamic.Message) is
      --  The request's "names": the parameter named on the command line.
      Names : constant ROSIDL.Dynamic.Array_Ref := Request ("names").As_Array;
   begin
      Names.Resize (1);
      Names.Element (1).Set_String (Pos (3));
   end Ask_For_Named_Parameter;

   function Answered_Value (Item : ROSIDL.Dynamic.Field_Ref) return Value is
      --  A ParameterValue of the node's reply: one of an unknown type is the
      --  node's error, said as such (not an internal error of rclada).
   begin
      return Get_Parameter_Value (Item);
   exception
      when E : Parameter_Error =>
         raise Command_Error with "the node answered a value rclada cannot read: "
           & Ada.Exceptions.Exception_Message (E);
   end Answered_Value;

   procedure Need (Count : Positive; What : String) is
   begin
      if Natural (Pos.Length) /= Count then
         raise Usage_Error with What;
      end if;
   end Need;
begin
   Check_Options (Args, "--timeout");
   if Pos.Is_Empty then
      raise Usage_Error with "missing sub-command (list, get, set, describe)";
   elsif Pos (1) = "list" then
      Need (2, "param list takes one node name");
      for N of Sorted_Names (Fully_Qualified (Pos (2))) loop
         Put_Line ("  " & N);
      end loop;
   elsif Pos (1) = "get" then
      Need (3, "param get takes a node name and a parameter name");
      declare
         Response : constant ROSIDL.Dynamic.Message :=
           Call (Fully_Qualified (Pos (2)), "get_parameters", "GetParameters",
                 Ask_For_Named_Parameter'Access);
         Values : constant ROSIDL.Dynamic.Array_Ref := Response ("values").As_Array;
      begin
         if Values.Length /= 1 then
            raise Command_Error with "the node answered" & Values.Length'Image & " values";
         end if;
         declare
            V : constant Value := Answered_Value (Values.Element (1));
         begin
            case V.Kind is
               when Not_Set =>
                  Put_Line ("Parameter not set.");
               when Bool_Type | Integer_Type | Double_Type | String_Type =>
                  Put_Line (Kind_Word (V.Kind) & " value is: " & Image (V));
               when others =>
                  Put_Line (Kind_Word (V.Kind) & " values are: " & Image (V));
            end case;
         end;
      end;
   elsif Pos (1) = "set" then
      Need (4, "param set takes a node name, a parameter name and a value");
      declare
         New_Value : constant Value := Parse (Pos (4), "<value>");
         procedure Fill (Request : ROSIDL.Dynamic.Message) is
            Params : constant ROSIDL.Dynamic.Array_Ref := Request ("parameters").As_Array;
         begin
            Params.Resize (1);
            Params.Element (1).Field_Reference ("name").Set_String (Pos (3));
            Put_Parameter_Value (Params.Element (1).Field_Reference ("value"), New_Value);
         end Fill;
         Response : constant ROSIDL.Dynamic.Message :=
           Call (Fully_Qualified (Pos (2)), "set_parameters", "SetParameters", Fill'Access);
         Results : constant ROSIDL.Dynamic.Array_Ref := Response ("results").As_Array;
      begin
         if Results.Length /= 1 then
            raise Command_Error with "the node answered" & Results.Length'Image & " results";
         end if;
         if Results.Element (1).Field_Reference ("successful").As_Bool.Element.all then
            Put_Line ("Set parameter successful");
         else
            raise Command_Error with "Setting parameter failed: "
              & Results.Element (1).Field_Reference ("reason").Get_String;
         end if;
      end;
   elsif Pos (1) = "delete" then
      Need (3, "param delete takes a node name and a parameter name");
      declare
         procedure Fill (Request : ROSIDL.Dynamic.Message) is
            Params : constant ROSIDL.Dynamic.Array_Ref := Request ("parameters").As_Array;
         begin
            Params.Resize (1);
            Params.Element (1).Field_Reference ("name").Set_String (Pos (3));
            --  Value type NOT_SET: undeclare, as rclcpp does.
         end Fill;
         Response : constant ROSIDL.Dynamic.Message :=
           Call (Fully_Qualified (Pos (2)), "set_parameters", "SetParameters", Fill'Access);
         Results : constant ROSIDL.Dynamic.Array_Ref := Response ("results").As_Array;
      begin
         if Results.Length = 1
           and then Results.Element (1).Field_Reference ("successful").As_Bool.Element.all
         then
            Put_Line ("Deleted parameter successfully");
         else
            raise Command_Error with "Deleting parameter failed"
              & (if Results.Length = 1
                 then ": " & Results.Element (1).Field_Reference ("reason").Get_String else "");
         end if;
      end;
   elsif Pos (1) = "load" then
      Need (3, "param load takes a node name and a parameter file");
      declare
         use RCL.YAML;
         Node_Name : constant String := Fully_Qualified (Pos (2));
         D         : constant Document := Parse_File (Pos (3));
         Names     : Text_Vectors.Vector;
         Values    : array (1 .. 1000) of Value;
         Count     : Natural := 0;

         procedure Flatten (Prefix : String; N : RCL.YAML.Node) is
         begin
            for I in 1 .. D.Length (N) loop
               if D.Kind (D.Item (N, I)) = Mapping then
                  Flatten (Prefix & D.Key (N, I) & ".", D.Item (N, I));
               elsif Count < Values'Last then
                  Count := Count + 1;
                  Names.Append (To_Unbounded_String (Prefix & D.Key (N, I)));
                  Values (Count) := From_YAML (D, D.Item (N, I));
               end if;
            end loop;
         end Flatten;

         procedure Fill (Request : ROSIDL.Dynamic.Message) is
            Params : constant ROSIDL.Dynamic.Array_Ref := Request ("parameters").As_Array;
         begin
            Params.Resize (Count);
            for I in 1 .. Count loop
               Params.Element (I).Field_Reference ("name").Set_String (To_String (Names (I)));
               Put_Parameter_Value (Params.Element (I).Field_Reference ("value"), Values (I));
            end loop;
         end Fill;
      begin
         if D.Kind (D.Root) = Mapping then
            for I in 1 .. D.Length (D.Root) loop
               declare
                  K : constant String := D.Key (D.Root, I);
                  V : constant RCL.YAML.Node := D.Item (D.Root, I);
               begin
                  if (K = "/**" or else Fully_Qualified (K) = Node_Name)
                    and then D.Kind (V) = Mapping
                  then
                     for J in 1 .. D.Length (V) loop
                        if D.Key (V, J) = "ros__parameters"
                          and then D.Kind (D.Item (V, J)) = Mapping
                        then
                           Flatten ("", D.Item (V, J));
                        end if;
                     end loop;
                  end if;
               end;
            end loop;
         end if;
         if Count = 0 then
            raise Command_Error with "Param file '" & Pos (3) & "' has no parameters for "
              & Node_Name;
         end if;
         declare
            Response : constant ROSIDL.Dynamic.Message :=
              Call (Node_Name, "set_parameters", "SetParameters", Fill'Access);
            Results  : constant ROSIDL.Dynamic.Array_Ref := Response ("results").As_Array;
         begin
            for I in 1 .. Natural'Min (Count, Results.Length) loop
               if Results.Element (I).Field_Reference ("successful").As_Bool.Element.all then
                  Put_Line ("Set parameter " & To_String (Names (I)) & " successful");
               else
                  Put_Line ("Set parameter " & To_String (Names (I)) & " failed: "
                            & Results.Element (I).Field_Reference ("reason").Get_String);
               end if;
            end loop;
         end;
      exception
         when E : Parse_Error =>
            raise Command_Error with Ada.Exceptions.Exception_Message (E);
      end;
   elsif Pos (1) = "dump" then
      Need (2, "param dump takes one node name");
      declare
         Node_Name : constant String := Fully_Qualified (Pos (2));
         Sorted    : constant Argument_Vectors.Vector := Sorted_Names (Node_Name);
      begin
         declare
            procedure Fill (Request : ROSIDL.Dynamic.Message) is
               Asked : constant ROSIDL.Dynamic.Array_Ref := Request ("names").As_Array;
            begin
               Asked.Resize (Natural (Sorted.Length));
               for I in 1 .. Natural (Sorted.Length) loop
                  Asked.Element (I).Set_String (Sorted (I));
               end loop;
            end Fill;
            Got    : constant ROSIDL.Dynamic.Message :=
              Call (Node_Name, "get_parameters", "GetParameters", Fill'Access);
            Values : constant ROSIDL.Dynamic.Array_Ref := Got ("values").As_Array;
         begin
            if Values.Length /= Natural (Sorted.Length) then
               raise Command_Error with "the node answered" & Values.Length'Image
                 & " values for" & Sorted.Length'Image & " parameters";
            end if;
            Put_Line (Node_Name & ":");
            Put_Line ("  ros__parameters:");
            for I in 1 .. Values.Length loop
               Put_Line ("    " & Sorted (I) & ": "
                         & YAML_Image (Answered_Value (Values.Element (I))));
            end loop;
         end;
      end;
   elsif Pos (1) = "describe" then
      Need (3, "param describe takes a node name and a parameter name");
      declare
         Response : constant ROSIDL.Dynamic.Message :=
           Call (Fully_Qualified (Pos (2)), "describe_parameters", "DescribeParameters",
                 Ask_For_Named_Parameter'Access);
         D : constant ROSIDL.Dynamic.Field_Ref := Response ("descriptors").As_Array (1);
         T : constant Natural := Natural (D.Field_Reference ("type").As_UInt8.Element.all);
      begin
         Put_Line ("Parameter name: " & D.Field_Reference ("name").Get_String);
         Put_Line ("  Type: " & (if T <= Parameter_Type'Pos (Parameter_Type'Last)
                                 then Type_Image (Parameter_Type'Val (T)) else "unknown"));
         if D.Field_Reference ("description").Get_String /= "" then
            Put_Line ("  Description: " & D.Field_Reference ("description").Get_String);
         end if;
         Put_Line ("  Constraints:");
         if D.Field_Reference ("read_only").As_Bool.Element.all then
            Put_Line ("    Read only: true");
         end if;
      end;
   else
      raise Usage_Error with "unknown param sub-command '" & Pos (1) & "'";
   end if;
exception
   when E : RCL.YAML.Parse_Error =>
      raise Command_Error with "bad value: " & Ada.Exceptions.Exception_Message (E);
end Param_Command;
