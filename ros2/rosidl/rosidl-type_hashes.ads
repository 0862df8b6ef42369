--  ROS 2 type hashes (REP 2011, version RIHS01), which Jazzy endpoints
--  announce in their USER_DATA ("typehash=RIHS01_<hex>;"): the SHA-256 of
--  the type's description (its fields and every type it refers to,
--  without defaults or constants) written as compact JSON.
--  Example:
--     pragma Assert
--       (Hash (ROSIDL.Interfaces.Message ("std_msgs", "String"))
--          = "RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18");
--
--  A service's request and response topics carry the hashes of its
--  <Name>_Request and <Name>_Response messages (as rmw_cyclonedds does).
with ROSIDL.Definitions;

package ROSIDL.Type_Hashes is

   Prefix : constant String := "RIHS01_";

   subtype Type_Hash is String (1 .. Prefix'Length + 64);
   --  "RIHS01_" then 64 lowercase hexadecimal digits.

   Zero : constant Type_Hash := Prefix & [1 .. 64 => '0'];
   --  The hash of an unknown type: Jazzy then matches by name only.

   function Description (Def : not null Definitions.Message_Access) return String;
   --  The hashed text: {"type_description": {...}, "referenced_type_
   --  descriptions": [...]} with the separators ", " and ": ", the
   --  referenced types sorted by name.

   function Hash (Def : not null Definitions.Message_Access) return Type_Hash;
   --  "RIHS01_" & SHA-256 (Description (Def)), cached per type.

   function Hash_Of_DDS_Type (DDS_Type_Name : String) return Type_Hash;
   --  The hash of the interface whose DDS type name is given
   --  ("std_msgs::msg::dds_::String_"): the one registered for it (Register),
   --  else the one computed from its definition on the search path; Zero
   --  when neither is known (a raw-CDR endpoint of a type this program does
   --  not know).

   procedure Register (DDS_Type_Name : String; Hash : Type_Hash);
   --  Makes Hash_Of_DDS_Type return Hash for DDS_Type_Name, whether the
   --  type is on the search path or not. RCL's typed API registers the hash
   --  of a generated type (computed by the generator) when it makes an
   --  endpoint of it, so that a user type whose definition is not on the
   --  search path announces its real hash. A second registration of the
   --  same name keeps the first hash.

end ROSIDL.Type_Hashes;
