--  rclada lifecycle nodes | get | set | list, as "ros2 lifecycle", through
--  the managed node's lifecycle_msgs services.
separate (Rclada_Commands)
procedure Lifecycle_Command (Args : Arguments) is

   Pos     : constant Arguments := Positional (Args);
   Timeout : constant Duration := Duration (Number_Option (Args, "--timeout", "5.0"));
   HT      : constant Character := Ada.Characters.Latin_1.HT;

   function Call (Node_Name, Service, Type_Name : String; Request : ROSIDL.Dynamic.Message)
     return ROSIDL.Dynamic.Message
   is
      Node : constant RCL.Nodes.Node := Tool_Node;
   begin
      return RCL.Clients.Call
        (Node, ROSIDL.Typesupport.Get_Service_Support ("lifecycle_msgs", Type_Name),
         Node_Name & "/" & Service, Request, Timeout);
   exception
      when RCL.RCL_Timeout =>
         raise Command_Error with "Node not found or not a lifecycle node: " & Node_Name
           & " (no answer from " & Node_Name & "/" & Service & " within" & Timeout'Image
           & " s)";
   end Call;

   function Request_Of (Type_Name : String) return ROSIDL.Dynamic.Message is
     (ROSIDL.Dynamic.Init (ROSIDL.Typesupport.Request_Support
        (ROSIDL.Typesupport.Get_Service_Support ("lifecycle_msgs", Type_Name))));

   function Image (State : ROSIDL.Dynamic.Field_Ref) return String is
     (State ("label").Get_String & " ["
      & Ada.Strings.Fixed.Trim (State ("id").As_UInt8.Element.all'Image, Ada.Strings.Left)
      & "]");

   --  "- configure [1]" and, with Details, its start and goal states.
   function Transitions (Node_Name : String; Graph : Boolean; Details : Boolean)
     return String
   is
      Response : constant ROSIDL.Dynamic.Message :=
        Call (Node_Name, (if Graph then "get_transition_graph" else "get_available_transitions"),
              "GetAvailableTransitions", Request_Of ("GetAvailableTransitions"));
      List     : constant ROSIDL.Dynamic.Array_Ref :=
        Response ("available_transitions").As_Array;
      Text     : Unbounded_String;
   begin
      for I in 1 .. List.Length loop
         declare
            D : constant ROSIDL.Dynamic.Field_Ref := List.Element (I);
         begin
            Append (Text, "- " & Image (D ("transition")) & LF);
            if Details then
               Append (Text, HT & "Start: " & D ("start_state")("label").Get_String & LF
                       & HT & "Goal: " & D ("goal_state")("label").Get_String & LF);
            end if;
         end;
      end loop;
      return To_String (Text);
   end Transitions;

   procedure Set (Node_Name, Transition : String) is
      Response : constant ROSIDL.Dynamic.Message :=
        Call (Node_Name, "get_available_transitions", "GetAvailableTransitions",
              Request_Of ("GetAvailableTransitions"));
      List     : constant ROSIDL.Dynamic.Array_Ref :=
        Response ("available_transitions").As_Array;
   begin
      for I in 1 .. List.Length loop
         declare
            T : constant ROSIDL.Dynamic.Field_Ref := List.Element (I)("transition");
         begin
            if T ("label").Get_String = Transition
              or else Ada.Strings.Fixed.Trim (T ("id").As_UInt8.Element.all'Image,
                                              Ada.Strings.Left) = Transition
            then
               declare
                  Request : constant ROSIDL.Dynamic.Message := Request_Of ("ChangeState");
               begin
                  Request ("transition")("id").As_UInt8.Element.all :=
                    T ("id").As_UInt8.Element.all;
                  Request ("transition")("label").Set_String (T ("label").Get_String);
                  if Boolean (Call (Node_Name, "change_state", "ChangeState", Request)
                                ("success").As_Bool.Element.all)
                  then
                     Put_Line ("Transitioning successful");
                  else
                     raise Command_Error with "Transitioning failed";
                  end if;
                  return;
               end;
            end if;
         end;
      end loop;
      raise Command_Error with "Unknown transition requested, available ones are:" & LF
        & Transitions (Node_Name, Graph => False, Details => False);
   end Set;

   procedure Nodes is
   begin
      for S of Graph.Service_Names_And_Types loop
         declare
            N : constant String := To_String (S.Name);
            Suffix : constant String := "/get_state";
         begin
            if To_String (S.Types) = "lifecycle_msgs/srv/GetState"
              and then N'Length > Suffix'Length
              and then N (N'Last - Suffix'Length + 1 .. N'Last) = Suffix
            then
               Put_Line (N (N'First .. N'Last - Suffix'Length));
            end if;
         end;
      end loop;
   end Nodes;

   procedure Need (Count : Positive; What : String) is
   begin
      if Natural (Pos.Length) /= Count then
         raise Usage_Error with "lifecycle " & Pos (1) & " takes " & What;
      end if;
   end Need;
begin
   if Pos.Is_Empty then
      raise Usage_Error with "missing sub-command (nodes, get, set, list)";
   elsif Pos (1) = "nodes" then
      Check_Options (Args, "--spin-time");
      Discover (Args);
      Nodes;
   elsif Pos (1) = "get" then
      Check_Options (Args, "--timeout");
      Need (2, "a node name");
      Put_Line (Image (Call (Fully_Qualified (Pos (2)), "get_state", "GetState",
                             Request_Of ("GetState")) ("current_state")));
   elsif Pos (1) = "set" then
      Check_Options (Args, "--timeout");
      Need (3, "a node name and a transition");
      Set (Fully_Qualified (Pos (2)), Pos (3));
   elsif Pos (1) = "list" then
      Check_Options (Args, "-a --all --timeout");
      Need (2, "a node name");
      Put_Lines (Transitions (Fully_Qualified (Pos (2)),
                              Graph => Has_Flag (Args, "-a", "--all"), Details => True));
   else
      raise Usage_Error with "unknown lifecycle sub-command '" & Pos (1) & "'";
   end if;
end Lifecycle_Command;
