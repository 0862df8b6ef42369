with Ada.Exceptions;
with Ada.Strings.Fixed;
with ROSIDL.CDR;
with ROSIDL.Typesupport;
with RCL.Clocks;
with RCL.DDS;
with RCL.Names;
with RCL.Node_Entities;
with RCL.Parameters.Stores;
with RCL.Publishers;
with RCL.QoS;
with RCL.Services;

package body RCL.Parameters.Serving is

   use ROSIDL.Dynamic;
   use Stores;

   Event_Support : ROSIDL.Typesupport.Message_Support;
   Event_Support_Set : Boolean := False;

   procedure Publish_Event (Node_Name : String; Names : Text_Vectors.Vector; Is_New : Boolean) is
      P : constant Publisher_Access := Store.Publisher_Of (Node_Name);
   begin
      if P = null or else not Event_Support_Set then
         return;
      end if;
      declare
         Event : constant Message := Init (Event_Support);
         Now   : constant RCL.DDS.Time_Ns := RCL.DDS.Now;
         use type RCL.DDS.Time_Ns;
         List  : constant Array_Ref :=
           Event ((if Is_New then "new_parameters" else "changed_parameters")).As_Array;
      begin
         Event ("stamp")("sec").As_Int32.Element.all := ROSIDL.Int32 (Now / 1_000_000_000);
         Event ("stamp")("nanosec").As_UInt32.Element.all :=
           ROSIDL.UInt32 (Now mod 1_000_000_000);
         Event ("node").Set_String (Node_Name);
         List.Resize (Natural (Names.Length));
         for I in 1 .. Natural (Names.Length) loop
            List.Element (I).Field_Reference ("name").Set_String (To_String (Names (I)));
            Put_Parameter_Value (List.Element (I).Field_Reference ("value"),
                                 Store.Get (Node_Name, To_String (Names (I))).Current);
         end loop;
         P.Publish_Raw (ROSIDL.CDR.Encode (Event));
      end;
   end Publish_Event;

   function Node_Of (Node : RCL.Nodes.Node'Class) return String is (Node.Fully_Qualified_Name);

   procedure Get_Parameters
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Req_Names : constant Array_Ref := Request ("names").As_Array;
      Values    : constant Array_Ref := Response ("values").As_Array;
   begin
      Values.Resize (Req_Names.Length);
      for I in 1 .. Req_Names.Length loop
         declare
            Name : constant String := Req_Names.Element (I).Get_String;
         begin
            if Store.Contains (Node_Of (Node), Name) then
               Put_Parameter_Value (Values.Element (I),
                                    Store.Get (Node_Of (Node), Name).Current);
            end if;
         end;
      end loop;
   end Get_Parameters;

   procedure Get_Parameter_Types
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Req_Names : constant Array_Ref := Request ("names").As_Array;
      Types     : UInt8_Array (1 .. Req_Names.Length);
   begin
      for I in Types'Range loop
         Types (I) := Parameter_Type'Pos
           (Describe (Node_Of (Node), Req_Names.Element (I).Get_String).Kind);
      end loop;
      Response ("types").Set_UInt8_Array (Types);
   end Get_Parameter_Types;

   function Assignment_Of (Parameter : Field_Ref) return Assignment is
   --  An rcl_interfaces/Parameter of a request. Parameter_Error naming it
   --  when its value's type is unknown (a peer's request: the callers answer
   --  the reason; the exception must not leave the request unanswered).
      Name : constant String := Parameter.Field_Reference ("name").Get_String;
   begin
      return (To_Unbounded_String (Name),
              Get_Parameter_Value (Parameter.Field_Reference ("value")));
   exception
      when E : Parameter_Error =>
         raise Parameter_Error with "parameter '" & RCL.Names.Shortened (Name) & "': "
           & Ada.Exceptions.Exception_Message (E);
   end Assignment_Of;

   function Try_Set (Node_Name : String; Parameter : Field_Ref) return String is
   begin
      declare
         Item : constant Assignment := Assignment_Of (Parameter);
      begin
         return Try_Set (Node_Name, To_String (Item.Name), Item.New_Value);
      end;
   exception
      when E : Parameter_Error =>
         return Ada.Exceptions.Exception_Message (E);
   end Try_Set;

   procedure Set_Parameters
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Params  : constant Array_Ref := Request ("parameters").As_Array;
      Results : constant Array_Ref := Response ("results").As_Array;
   begin
      Results.Resize (Params.Length);
      for I in 1 .. Params.Length loop
         declare
            Reason : constant String := Try_Set (Node_Of (Node), Params.Element (I));
         begin
            Results.Element (I).Field_Reference ("successful").As_Bool.Element.all :=
              Reason = "";
            Results.Element (I).Field_Reference ("reason").Set_String (Reason);
         end;
      end loop;
   end Set_Parameters;

   procedure Set_Parameters_Atomically
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Params : constant Array_Ref := Request ("parameters").As_Array;

      function Reason return String is
         List : Assignment_Array (1 .. Params.Length);
      begin
         for I in List'Range loop
            List (I) := Assignment_Of (Params.Element (I));
         end loop;
         return Try_Set_Atomically (Node_Of (Node), List);
      exception
         when E : Parameter_Error =>
            return Ada.Exceptions.Exception_Message (E);
      end Reason;

      Answer : constant String := Reason;
   begin
      Response ("result")("successful").As_Bool.Element.all := Answer = "";
      Response ("result")("reason").Set_String (Answer);
   end Set_Parameters_Atomically;

   procedure Describe_Parameters
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Req_Names : constant Array_Ref := Request ("names").As_Array;
      Descs     : constant Array_Ref := Response ("descriptors").As_Array;
   begin
      Descs.Resize (Req_Names.Length);
      for I in 1 .. Req_Names.Length loop
         declare
            D : constant Descriptor := Describe (Node_Of (Node), Req_Names.Element (I).Get_String);
            R : constant Field_Ref := Descs.Element (I);
         begin
            R.Field_Reference ("name").Set_String (To_String (D.Name));
            R.Field_Reference ("type").As_UInt8.Element.all := Parameter_Type'Pos (D.Kind);
            R.Field_Reference ("description").Set_String (To_String (D.Description));
            R.Field_Reference ("read_only").As_Bool.Element.all := D.Read_Only;
         end;
      end loop;
   end Describe_Parameters;

   procedure List_Parameters
     (Node : in out RCL.Nodes.Node'Class; Request : Message; Response : in out Message)
   is
      Prefixes : constant Array_Ref := Request ("prefixes").As_Array;
      Depth    : constant Natural := Natural'Min
        (Natural'Last / 2, Natural (ROSIDL.UInt64'Min (Request ("depth").As_UInt64.Element.all,
                                                        ROSIDL.UInt64 (Natural'Last / 2))));
      Found    : Text_Vectors.Vector;
      Groups   : Text_Vectors.Vector;

      function Dots (S : String) return Natural is
        (Ada.Strings.Fixed.Count (S, "."));
   begin
      for N of Names (Node_Of (Node)) loop
         declare
            Name : constant String := To_String (N);
            Ok   : Boolean := Prefixes.Length = 0;
         begin
            for I in 1 .. Prefixes.Length loop
               declare
                  P : constant String := Prefixes.Element (I).Get_String;
               begin
                  if Name = P
                    or else (Name'Length > P'Length
                             and then Name (Name'First .. Name'First + P'Length) = P & ".")
                  then
                     Ok := Ok or (Depth = 0 or else Dots (Name) - Dots (P) <= Depth);
                  end if;
               end;
            end loop;
            if Prefixes.Length = 0 and then Depth > 0 and then Dots (Name) >= Depth then
               Ok := False;
            end if;
            if Ok then
               Found.Append (N);
               declare
                  Last_Dot : constant Natural :=
                    Ada.Strings.Fixed.Index (Name, ".", Ada.Strings.Backward);
               begin
                  if Last_Dot > 0
                    and then not Groups.Contains
                      (To_Unbounded_String (Name (Name'First .. Last_Dot - 1)))
                  then
                     Groups.Append (To_Unbounded_String (Name (Name'First .. Last_Dot - 1)));
                  end if;
               end;
            end if;
         end;
      end loop;
      declare
         Out_Names : constant Array_Ref := Response ("result")("names").As_Array;
         Out_Pref  : constant Array_Ref := Response ("result")("prefixes").As_Array;
      begin
         Out_Names.Resize (Natural (Found.Length));
         for I in 1 .. Natural (Found.Length) loop
            Out_Names.Element (I).Set_String (To_String (Found (I)));
         end loop;
         Out_Pref.Resize (Natural (Groups.Length));
         for I in 1 .. Natural (Groups.Length) loop
            Out_Pref.Element (I).Set_String (To_String (Groups (I)));
         end loop;
      end;
   end List_Parameters;

   procedure Serve (Node : in out RCL.Nodes.Node'Class) is
      use ROSIDL.Typesupport;
      function Srv (Name : String) return Service_Support is
        (Get_Service_Support ("rcl_interfaces", Name));
      Q : constant RCL.QoS.Profile := RCL.QoS.Parameters;
      Declared : Boolean;
   begin
      if RCL.Node_Entities.Serves_Parameters (Node) then
         return;  --  Done by Nodes.Init already.
      end if;
      RCL.Node_Entities.Set_Serves_Parameters (Node);
      if not Event_Support_Set then
         Event_Support := Get_Message_Support ("rcl_interfaces", "ParameterEvent");
         Event_Support_Set := True;
      end if;
      if not Has_Parameter (Node, "use_sim_time") then
         --  As every ROS 2 node has it. Read-only here: simulated time is
         --  chosen at start (--ros-args -p use_sim_time:=true, RCL.Clocks).
         Store.Insert
           (Node.Fully_Qualified_Name, "use_sim_time",
            (Desc    => (Name        => To_Unbounded_String ("use_sim_time"),
                         Kind        => Bool_Type,
                         Description => To_Unbounded_String
                           ("ROS time follows /clock (set at start only)"),
                         Read_Only   => True),
             Current => To_Value (RCL.Clocks.Sim_Time_Enabled
                                  or else RCL.Clocks.Sim_Time_Requested)),
            Declared);
      end if;
      RCL.Services.Serve (Node, Srv ("GetParameters"), "~/get_parameters",
                          Get_Parameters'Access, Q);
      RCL.Services.Serve (Node, Srv ("GetParameterTypes"), "~/get_parameter_types",
                          Get_Parameter_Types'Access, Q);
      RCL.Services.Serve (Node, Srv ("SetParameters"), "~/set_parameters",
                          Set_Parameters'Access, Q);
      RCL.Services.Serve (Node, Srv ("SetParametersAtomically"), "~/set_parameters_atomically",
                          Set_Parameters_Atomically'Access, Q);
      RCL.Services.Serve (Node, Srv ("DescribeParameters"), "~/describe_parameters",
                          Describe_Parameters'Access, Q);
      RCL.Services.Serve (Node, Srv ("ListParameters"), "~/list_parameters",
                          List_Parameters'Access, Q);
      Store.Set_Publisher
        (Node.Fully_Qualified_Name,
         new RCL.Publishers.Publisher'
           (Node.Publish_Raw (DDS_Type_Name (Event_Support), "/parameter_events",
                              RCL.QoS.Parameter_Events)));
   end Serve;

end RCL.Parameters.Serving;
