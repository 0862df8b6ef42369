with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with GNAT.SHA256;
with System.Address_Image;
with ROSIDL.Interfaces;

package body ROSIDL.Type_Hashes is

   use Ada.Strings.Unbounded;
   use ROSIDL.Definitions;

   --  Field type identifiers of type_description_interfaces/msg/FieldType.
   Nested_Type_Id : constant := 1;
   Array_Offset   : constant := 48;
   Bounded_Offset : constant := 96;
   Sequence_Offset : constant := 144;

   function Element_Id (T : Field_Type) return Natural is
     (case T.Kind is
         when Message_Kind => Nested_Type_Id,
         when Int8_Kind    => 2,
         when UInt8_Kind | Char_Kind => 3,   --  rosidl maps "char" to uint8
         when Int16_Kind   => 4,
         when UInt16_Kind  => 5,
         when Int32_Kind   => 6,
         when UInt32_Kind  => 7,
         when Int64_Kind   => 8,
         when UInt64_Kind  => 9,
         when Float32_Kind => 10,
         when Float64_Kind => 11,
         when Bool_Kind    => 15,
         when Byte_Kind    => 16,
         when String_Kind  => (if T.String_Bound > 0 then 21 else 17),
         when WString_Kind => (if T.String_Bound > 0 then 22 else 18));

   function Type_Id (T : Field_Type) return Natural is
     (Element_Id (T)
      + (case T.Collection is
            when Single             => 0,
            when Fixed_Array        => Array_Offset,
            when Bounded_Sequence   => Bounded_Offset,
            when Unbounded_Sequence => Sequence_Offset));

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Quoted (S : String) return String is ('"' & S & '"');
   --  Interface and field names are identifiers: nothing to escape.

   function Individual (Def : not null Message_Access) return String is
      Text : Unbounded_String :=
        To_Unbounded_String ("{""type_name"": " & Quoted (Full_Name (Def.all))
                             & ", ""fields"": [");
   begin
      for I in Def.Fields.First_Index .. Def.Fields.Last_Index loop
         declare
            F : Field renames Def.Fields (I);
            T : Field_Type renames F.Of_Type;
         begin
            Append (Text, (if I > Def.Fields.First_Index then ", " else "")
                    & "{""name"": " & Quoted (To_String (F.Name))
                    & ", ""type"": {""type_id"": " & Image (Type_Id (T))
                    & ", ""capacity"": " & Image (T.Size)
                    & ", ""string_capacity"": " & Image (T.String_Bound)
                    & ", ""nested_type_name"": "
                    & Quoted (if T.Kind = Message_Kind then Full_Name (T.Nested.all) else "")
                    & "}}");
         end;
      end loop;
      return To_String (Text) & "]}";
   end Individual;

   package Text_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);
   --  Full type name -> its individual description; ordered by name, as the
   --  referenced types must be.

   procedure Collect (Def : not null Message_Access; Into : in out Text_Maps.Map) is
   begin
      for F of Def.Fields loop
         if F.Of_Type.Kind = Message_Kind
           and then not Into.Contains (Full_Name (F.Of_Type.Nested.all))
         then
            Into.Insert (Full_Name (F.Of_Type.Nested.all), Individual (F.Of_Type.Nested));
            Collect (F.Of_Type.Nested, Into);
         end if;
      end loop;
   end Collect;

   function Description (Def : not null Message_Access) return String is
      Referenced : Text_Maps.Map;
      Text       : Unbounded_String;
   begin
      Collect (Def, Referenced);
      for D of Referenced loop
         Append (Text, (if Length (Text) > 0 then ", " else "") & D);
      end loop;
      return "{""type_description"": " & Individual (Def)
        & ", ""referenced_type_descriptions"": [" & To_String (Text) & "]}";
   end Description;

   protected Cache is
      function Find (Name : String; Found : out Boolean) return Type_Hash;
      procedure Store (Name : String; Hash : Type_Hash);
   private
      Hashes : Text_Maps.Map;
   end Cache;

   protected body Cache is
      function Find (Name : String; Found : out Boolean) return Type_Hash is
         Position : constant Text_Maps.Cursor := Hashes.Find (Name);
      begin
         Found := Text_Maps.Has_Element (Position);
         return (if Found then Text_Maps.Element (Position) else Zero);
      end Find;

      procedure Store (Name : String; Hash : Type_Hash) is
      begin
         Hashes.Include (Name, Hash);
      end Store;
   end Cache;

   function Hash (Def : not null Message_Access) return Type_Hash is
      Found  : Boolean;
      Key    : constant String :=
        Full_Name (Def.all) & "@" & System.Address_Image (Def.all'Address);
      --  Two definitions may share a name (Jazzy's and Humble's
      --  rmw_dds_common); definitions are never freed.
      Cached : constant Type_Hash := Cache.Find (Key, Found);
   begin
      if Found then
         return Cached;
      end if;
      return Result : constant Type_Hash := Prefix & GNAT.SHA256.Digest (Description (Def)) do
         Cache.Store (Key, Result);
      end return;
   end Hash;

   package Registered_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Type_Hash);

   protected Registry is
      procedure Add (DDS_Type_Name : String; Hash : Type_Hash);
      function Find (DDS_Type_Name : String; Found : out Boolean) return Type_Hash;
   private
      Hashes : Registered_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Add (DDS_Type_Name : String; Hash : Type_Hash) is
      begin
         if not Hashes.Contains (DDS_Type_Name) then
            Hashes.Insert (DDS_Type_Name, Hash);
         end if;
      end Add;

      function Find (DDS_Type_Name : String; Found : out Boolean) return Type_Hash is
         Position : constant Registered_Maps.Cursor := Hashes.Find (DDS_Type_Name);
      begin
         Found := Registered_Maps.Has_Element (Position);
         return (if Found then Registered_Maps.Element (Position) else Zero);
      end Find;
   end Registry;

   procedure Register (DDS_Type_Name : String; Hash : Type_Hash) is
   begin
      Registry.Add (DDS_Type_Name, Hash);
   end Register;

   function Hash_Of_DDS_Type (DDS_Type_Name : String) return Type_Hash is
      Found      : Boolean;
      Registered : constant Type_Hash := Registry.Find (DDS_Type_Name, Found);
   begin
      if Found then
         return Registered;
      end if;
      return Hash (ROSIDL.Interfaces.Message_By_DDS_Name (DDS_Type_Name));
   exception
      when ROSIDL.Unknown_Type | ROSIDL.Definition_Error =>
         return Zero;
   end Hash_Of_DDS_Type;

end ROSIDL.Type_Hashes;
