--  What a registry of generated types lists (rosidl_generate --registry
--  UNIT writes UNIT.Types), for tests that go over every generated type:
--  Example:
--     for T of ROSIDL.Static.Bundled_Types.Types loop
--        Put_Line (T.Full_Name.all & (if T.Is_Bounded then " (bounded)" else ""));
--     end loop;
with Ada.Streams;
with ROSIDL.CDR;

package ROSIDL.Static.Registries is

   type Name_Access is access constant String;

   type Recode_Access is access function
     (Data : Ada.Streams.Stream_Element_Array; Order : ROSIDL.CDR.Byte_Order)
      return Ada.Streams.Stream_Element_Array;
   type Recode_Into_Access is access procedure
     (Data   : Ada.Streams.Stream_Element_Array;
      Buffer : out Ada.Streams.Stream_Element_Array;
      Last   : out Ada.Streams.Stream_Element_Offset;
      Order  : ROSIDL.CDR.Byte_Order);
   type Check_Access is access function (Data : Ada.Streams.Stream_Element_Array) return Boolean;
   type Default_Access is access function return Ada.Streams.Stream_Element_Array;

   type Type_Entry is record
      Full_Name, DDS_Type_Name, Type_Hash : Name_Access;
      Is_Bounded  : Boolean;
      Recode      : Recode_Access;
      --  Handling.Recode: Encode (Decode (Data), Order).
      Recode_Into : Recode_Into_Access;
      --  Handling.Recode_Into: the same into Buffer (Encode_Error when
      --  Buffer is too small).
      Round_Trips : Check_Access;
      --  Handling.Round_Trips.
      Default     : Default_Access;
      --  Handling.Encode_Default: a message of default values, encoded.
   end record;

   type Type_Entries is array (Positive range <>) of Type_Entry;

end ROSIDL.Static.Registries;
