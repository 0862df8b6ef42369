--  The parameters of every node of the process: descriptors and current
--  values by (node, name), each node's validator and /parameter_events
--  publisher, and the overrides (--ros-args, parameter files) waiting for
--  their declaration. One protected object: every operation is task-safe.
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Vectors;
with RCL.Publishers;

private package RCL.Parameters.Stores is

   type Entry_Record is record
      Desc    : Descriptor;
      Current : Value;
   end record;

   package Entry_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Entry_Record);
   package Validator_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Validator);

   type Publisher_Access is access RCL.Publishers.Publisher;
   package Publisher_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (String, Publisher_Access);

   type Override is record
      Pattern, Name : Unbounded_String;
      New_Value     : Value;
      Origin        : Unbounded_String;
      --  Where it was given: "p.yaml:4:11", "--ros-args -p rate"; "" unknown.
   end record;

   package Override_Vectors is new Ada.Containers.Vectors (Positive, Override);

   function Matches (Pattern, Node_Name : String) return Boolean;
   --  An override's node pattern ("/**", a full name, or a full name with
   --  rcl's wildcards: "/**" for any namespace, "*" for any one name, as in
   --  "/**/talker", "/robots/*") applies to Node_Name (fully qualified). A
   --  pattern without a leading '/' is absolute as in rclcpp: "talker" and
   --  "-p talker:rate:=5" mean "/talker", not a talker in another namespace.

   protected Store is
      procedure Insert (Node_Name, Name : String; E : Entry_Record; Done : out Boolean);
      function Contains (Node_Name, Name : String) return Boolean;
      function Get (Node_Name, Name : String) return Entry_Record;
      procedure Put_Value (Node_Name, Name : String; V : Value);
      function Names_Of (Node_Name : String) return Text_Vectors.Vector;
      procedure Set_Validator (Node_Name : String; Check : Validator);
      function Validator_Of (Node_Name : String) return Validator;
      procedure Set_Publisher (Node_Name : String; P : Publisher_Access);
      function Publisher_Of (Node_Name : String) return Publisher_Access;
      procedure Add_Override (O : Override);
      procedure Clear_Overrides;
      procedure Find_Override
        (Node_Name, Name : String; Found : out Boolean; O : out Override);
      --  The last override of Name that applies to Node_Name.
      procedure Mark_Loaded (Was_Loaded : out Boolean);
   private
      Entries    : Entry_Maps.Map;
      Validators : Validator_Maps.Map;
      Publishers : Publisher_Maps.Map;
      Overrides  : Override_Vectors.Vector;
      Loaded     : Boolean := False;
   end Store;

end RCL.Parameters.Stores;
