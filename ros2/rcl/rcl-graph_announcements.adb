with Ada.Containers.Vectors;
with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with ROSIDL.CDR;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Interfaces;
with ROSIDL.Mutexes;
with ROSIDL.Parser;
with ROSIDL.Type_Hashes;
with ROSIDL.Typesupport;
with RCL.Logging;
with RCL.Process_Context;
with RCL.QoS;

package body RCL.Graph_Announcements is

   use Ada.Strings.Unbounded;
   use RCL.Graph;
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
   Lock : ROSIDL.Mutexes.Mutex;

   --  State, guarded by Lock.
   Nodes      : Node_Vectors.Vector;
   Next_Id    : Node_Id := 1;
   type Writer_Access is access RCL.DDS.Writer;
   Writer     : Writer_Access;
   Support    : ROSIDL.Typesupport.Message_Support;
   type Bytes_Access is access RCL.DDS.Byte_Array;
   Last_Sample : Bytes_Access;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.DDS.Byte_Array, Bytes_Access);

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
        (Writer.all, RCL.Process_Context.Participant.all, Topic_Name, Type_Name,
         (RCL.QoS.Default with delta Depth => 1, Durability => RCL.QoS.Transient_Local),
         User_Data =>
           (if Layout = Jazzy_16
            then "typehash="
                 & ROSIDL.Type_Hashes.Hash (ROSIDL.Typesupport.Definition (Support)) & ";"
            else ""));
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
        (Gid_Bytes (RCL.DDS.Instance_GUID (RCL.Process_Context.Participant.all)));
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
      declare
         Sample : constant RCL.DDS.Byte_Array := ROSIDL.CDR.Encode (Msg);
      begin
         RCL.DDS.Write (Writer.all, Sample);
         Free (Last_Sample);
         Last_Sample := new RCL.DDS.Byte_Array'(Sample);
      end;
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

   --  Update with Change applied to the entry of node Id, if Id is known.
   procedure Update_Node
     (Id : Node_Id; Change : not null access procedure (Item : in out Node_Entry))
   is
      procedure Change_Known_Node is
         I : constant Natural := Index (Id);
      begin
         if I > 0 then
            Change (Nodes (I));
         end if;
      end Change_Known_Node;
   begin
      if Id /= No_Node then
         Update (Change_Known_Node'Access);
      end if;
   end Update_Node;

   type Endpoint_Side is (Readers, Writers);

   procedure Add (Id : Node_Id; Side : Endpoint_Side; Endpoint : RCL.DDS.GUID) is
      procedure Change (Item : in out Node_Entry) is
      begin
         case Side is
            when Readers => Item.Readers.Append (Endpoint);
            when Writers => Item.Writers.Append (Endpoint);
         end case;
      end Change;
   begin
      Update_Node (Id, Change'Access);
   end Add;

   procedure Remove (Id : Node_Id; Side : Endpoint_Side; Endpoint : RCL.DDS.GUID) is
      procedure Delete (List : in out GUID_Vectors.Vector) is
         Pos : constant Natural := List.Find_Index (Endpoint);
      begin
         if Pos > 0 then
            List.Delete (Pos);
         end if;
      end Delete;

      procedure Change (Item : in out Node_Entry) is
      begin
         case Side is
            when Readers => Delete (Item.Readers);
            when Writers => Delete (Item.Writers);
         end case;
      end Change;
   begin
      Update_Node (Id, Change'Access);
   end Remove;

   procedure Add_Writer (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
   begin
      Add (Id, Writers, Endpoint);
   end Add_Writer;

   procedure Remove_Writer (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
   begin
      Remove (Id, Writers, Endpoint);
   end Remove_Writer;

   procedure Add_Reader (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
   begin
      Add (Id, Readers, Endpoint);
   end Add_Reader;

   procedure Remove_Reader (Id : Node_Id; Endpoint : RCL.DDS.GUID) is
   begin
      Remove (Id, Readers, Endpoint);
   end Remove_Reader;

   function Announcement return RCL.DDS.Byte_Array is
   begin
      Lock.Seize;
      return Result : constant RCL.DDS.Byte_Array :=
        (if Last_Sample = null then [1 .. 0 => 0] else Last_Sample.all)
      do
         Lock.Release;
      end return;
   end Announcement;

end RCL.Graph_Announcements;
