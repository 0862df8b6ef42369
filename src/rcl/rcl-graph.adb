with Ada.Containers.Vectors;
with Ada.Environment_Variables;
with Ada.Exceptions;
with ROSIDL.CDR;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Interfaces;
with ROSIDL.Parser;
with ROSIDL.Typesupport;
with RCL.Contexts;
with RCL.Logging;
with RCL.QoS;

package body RCL.Graph is

   use Ada.Strings.Unbounded;
   use type RCL.DDS.GUID;

   package GUID_Vectors is new Ada.Containers.Vectors (Positive, RCL.DDS.GUID);

   type Node_Entry is record
      Id        : Node_Id;
      Namespace : Unbounded_String;
      Name      : Unbounded_String;
      Readers   : GUID_Vectors.Vector;
      Writers   : GUID_Vectors.Vector;
   end record;

   package Node_Vectors is new Ada.Containers.Vectors (Positive, Node_Entry);

   --  A mutex: updates and their publication are serialized, so the last
   --  message written is always the latest state.
   protected Lock is
      entry Seize;
      procedure Release;
   private
      Busy : Boolean := False;
   end Lock;

   protected body Lock is
      entry Seize when not Busy is
      begin
         Busy := True;
      end Seize;
      procedure Release is
      begin
         Busy := False;
      end Release;
   end Lock;

   --  State, guarded by Lock.
   Nodes      : Node_Vectors.Vector;
   Next_Id    : Node_Id := 1;
   type Writer_Access is access RCL.DDS.Writer;
   Writer     : Writer_Access;
   Support    : ROSIDL.Typesupport.Message_Support;
   Layout_Set : Boolean := False;
   The_Layout : GID_Layout := Humble_24;

   function Default_Layout return GID_Layout is
      Distro : constant String := Ada.Environment_Variables.Value ("ROS_DISTRO", "humble");
   begin
      return (if Distro in "jazzy" | "kilted" | "rolling" then Jazzy_16 else Humble_24);
   end Default_Layout;

   procedure Set_Layout (Layout : GID_Layout) is
   begin
      The_Layout := Layout;
      Layout_Set := True;
   end Set_Layout;

   function Layout return GID_Layout is
     (if Layout_Set then The_Layout else Default_Layout);

   --  Jazzy's Gid: char[16]; the other two messages resolve to it.
   function Jazzy_Resolver
     (Package_Name, Name : String; Where : ROSIDL.Definitions.Source_Position)
      return ROSIDL.Definitions.Message_Access
   is
   begin
      if Package_Name = "rmw_dds_common" and then Name = "Gid" then
         return ROSIDL.Parser.Parse_Message
           ("rmw_dds_common", "Gid", "char[16] data", File => "(Jazzy Gid)");
      elsif Package_Name = "rmw_dds_common" and then Name = "NodeEntitiesInfo" then
         return ROSIDL.Parser.Parse_Message
           ("rmw_dds_common", "NodeEntitiesInfo",
            "string<=256 node_namespace" & ASCII.LF & "string<=256 node_name" & ASCII.LF
            & "Gid[] reader_gid_seq" & ASCII.LF & "Gid[] writer_gid_seq",
            File => "(Jazzy NodeEntitiesInfo)", Resolve => Jazzy_Resolver'Access);
      end if;
      return ROSIDL.Parser.Search_Path_Resolver (Package_Name, Name, Where);
   end Jazzy_Resolver;

   procedure Open is
   begin
      if Writer /= null then
         return;
      end if;
      if Layout = Humble_24 then
         Support := ROSIDL.Typesupport.To_Support
           (ROSIDL.Interfaces.Message ("rmw_dds_common", "ParticipantEntitiesInfo"));
      else
         Support := ROSIDL.Typesupport.To_Support
           (ROSIDL.Parser.Parse_Message
              ("rmw_dds_common", "ParticipantEntitiesInfo",
               "Gid gid" & ASCII.LF & "NodeEntitiesInfo[] node_entities_info_seq",
               File => "(Jazzy ParticipantEntitiesInfo)", Resolve => Jazzy_Resolver'Access));
      end if;
      Writer := new RCL.DDS.Writer;
      RCL.DDS.Create
        (Writer.all, RCL.Contexts.Participant.all, Topic_Name, Type_Name,
         (RCL.QoS.Default with delta Depth => 1, Durability => RCL.QoS.Transient_Local));
   end Open;

   function Gid_Bytes (Id : RCL.DDS.GUID) return ROSIDL.Dynamic.UInt8_Array is
      Size   : constant Positive := (if Layout = Humble_24 then 24 else 16);
      Result : ROSIDL.Dynamic.UInt8_Array (1 .. Size) := [others => 0];
   begin
      for I in Id'Range loop
         Result (I) := Id (I);
      end loop;
      return Result;
   end Gid_Bytes;

   procedure Publish is
      use ROSIDL.Dynamic;
      Msg  : constant Message := Init (Support);
      List : constant Array_Ref := Msg ("node_entities_info_seq").As_Array;
   begin
      Msg ("gid") ("data").Set_UInt8_Array
        (Gid_Bytes (RCL.DDS.Instance_GUID (RCL.Contexts.Participant.all)));
      List.Resize (Natural (Nodes.Length));
      for I in 1 .. Natural (Nodes.Length) loop
         declare
            N : constant Node_Entry := Nodes (I);
            E : constant Field_Ref := List.Element (I);
            procedure Put (Field : String; Gids : GUID_Vectors.Vector) is
               Seq : constant Array_Ref := E (Field).As_Array;
            begin
               Seq.Resize (Natural (Gids.Length));
               for J in 1 .. Natural (Gids.Length) loop
                  Seq.Element (J) ("data").Set_UInt8_Array (Gid_Bytes (Gids (J)));
               end loop;
            end Put;
         begin
            E ("node_namespace").Set_String (To_String (N.Namespace));
            E ("node_name").Set_String (To_String (N.Name));
            Put ("reader_gid_seq", N.Readers);
            Put ("writer_gid_seq", N.Writers);
         end;
      end loop;
      RCL.DDS.Write (Writer.all, ROSIDL.CDR.Encode (Msg));
   end Publish;

   --  Runs Change then republishes, under Lock; never raises.
   procedure Update (Change : not null access procedure) is
   begin
      Lock.Seize;
      begin
         Open;
         Change.all;
         Publish;
      exception
         when E : others =>
            RCL.Logging.Warn ("publishing ros_discovery_info: "
                              & Ada.Exceptions.Exception_Message (E), Logger => "rcl");
      end;
      Lock.Release;
   end Update;

   function Index (Id : Node_Id) return Natural is
   begin
      for I in 1 .. Natural (Nodes.Length) loop
         if Nodes (I).Id = Id then
            return I;
         end if;
      end loop;
      return 0;
   end Index;

   procedure Add_Node (Namespace, Name : String; Id : out Node_Id) is
      New_Id : Node_Id := No_Node;
      procedure Change is
      begin
         New_Id := Next_Id;
         Next_Id := Next_Id + 1;
         Nodes.Append (Node_Entry'(New_Id, To_Unbounded_String (Namespace),
                                   To_Unbounded_String (Name),
                                   GUID_Vectors.Empty_Vector, GUID_Vectors.Empty_Vector));
      end Change;
   begin
      Update (Change'Access);
      Id := New_Id;
   end Add_Node;

   procedure Remove_Node (Id : Node_Id) is
      procedure Change is
         I : constant Natural := Index (Id);
      begin
         if I > 0 then
            Nodes.Delete (I);
         end if;
      end Change;
   begin
      if Id /= No_Node then
         Update (Change'Access);
      end if;
   end Remove_Node;

   procedure Add_Writer (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
      procedure Change is
         I : constant Natural := Index (Id);
      begin
         if I > 0 then
            Nodes (I).Writers.Append (Endpoint);
         end if;
      end Change;
   begin
      Update (Change'Access);
   end Add_Writer;

   procedure Remove_Writer (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
      procedure Change is
         I : constant Natural := Index (Id);
      begin
         if I > 0 then
            declare
               Pos : constant Natural := Nodes (I).Writers.Find_Index (Endpoint);
            begin
               if Pos > 0 then
                  Nodes (I).Writers.Delete (Pos);
               end if;
            end;
         end if;
      end Change;
   begin
      if Id /= No_Node then
         Update (Change'Access);
      end if;
   end Remove_Writer;

   procedure Add_Reader (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
      procedure Change is
         I : constant Natural := Index (Id);
      begin
         if I > 0 then
            Nodes (I).Readers.Append (Endpoint);
         end if;
      end Change;
   begin
      Update (Change'Access);
   end Add_Reader;

   -------------
   -- Queries --
   -------------

   function ROS_Type_Name (DDS_Type_Name : String) return String is
      Marker : constant String := "::dds_::";
      Result : Unbounded_String;
      I      : Natural := DDS_Type_Name'First;
   begin
      if DDS_Type_Name'Length < Marker'Length + 2
        or else DDS_Type_Name (DDS_Type_Name'Last) /= '_'
      then
         return DDS_Type_Name;
      end if;
      while I <= DDS_Type_Name'Last - 1 loop
         if I + Marker'Length - 1 <= DDS_Type_Name'Last
           and then DDS_Type_Name (I .. I + Marker'Length - 1) = Marker
         then
            Append (Result, '/');
            I := I + Marker'Length;
         elsif I + 1 <= DDS_Type_Name'Last and then DDS_Type_Name (I .. I + 1) = "::" then
            Append (Result, '/');
            I := I + 2;
         else
            Append (Result, DDS_Type_Name (I));
            I := I + 1;
         end if;
      end loop;
      return To_String (Result);
   end ROS_Type_Name;

   package Info_Vectors is new Ada.Containers.Vectors (Positive, Topic_Info);

   procedure Count
     (List : in out Info_Vectors.Vector; Lines : String; Publications : Boolean)
   is
      Start : Positive := Lines'First;
   begin
      for I in Lines'Range loop
         if Lines (I) = ASCII.LF then
            declare
               Line : constant String := Lines (Start .. I - 1);
               Tab  : Natural := 0;
            begin
               for J in Line'Range loop
                  if Line (J) = ASCII.HT then
                     Tab := J;
                     exit;
                  end if;
               end loop;
               if Tab > Line'First + 2 and then Line (Line'First .. Line'First + 2) = "rt/" then
                  declare
                     Name  : constant String := Line (Line'First + 2 .. Tab - 1);
                     Typ   : constant String := ROS_Type_Name (Line (Tab + 1 .. Line'Last));
                     Found : Boolean := False;
                  begin
                     for E of List loop
                        if E.Name = Name and then E.Type_Name = Typ then
                           if Publications then
                              E.Publishers := E.Publishers + 1;
                           else
                              E.Subscribers := E.Subscribers + 1;
                           end if;
                           Found := True;
                        end if;
                     end loop;
                     if not Found then
                        List.Append
                          (Topic_Info'(To_Unbounded_String (Name), To_Unbounded_String (Typ),
                                       (if Publications then 1 else 0),
                                       (if Publications then 0 else 1)));
                     end if;
                  end;
               end if;
            end;
            Start := I + 1;
         end if;
      end loop;
   end Count;

   function Topics return Topic_Info_Array is
      function "<" (L, R : Topic_Info) return Boolean is
        (L.Name < R.Name or else (L.Name = R.Name and then L.Type_Name < R.Type_Name));
      package Sorting is new Info_Vectors.Generic_Sorting;
      List : Info_Vectors.Vector;
      P    : constant access RCL.DDS.Participant := RCL.Contexts.Participant;
   begin
      Count (List, RCL.DDS.Endpoints (P.all, Publications => True), True);
      Count (List, RCL.DDS.Endpoints (P.all, Publications => False), False);
      Sorting.Sort (List);
      return Result : Topic_Info_Array (1 .. Natural (List.Length)) do
         for I in Result'Range loop
            Result (I) := List (I);
         end loop;
      end return;
   end Topics;

   function Count_Publishers (Topic : String) return Natural is
      N : Natural := 0;
   begin
      for T of Topics loop
         if T.Name = Topic then
            N := N + T.Publishers;
         end if;
      end loop;
      return N;
   end Count_Publishers;

   function Count_Subscribers (Topic : String) return Natural is
      N : Natural := 0;
   begin
      for T of Topics loop
         if T.Name = Topic then
            N := N + T.Subscribers;
         end if;
      end loop;
      return N;
   end Count_Subscribers;

end RCL.Graph;
