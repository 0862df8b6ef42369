with Ada.Containers.Vectors;
with Ada.Environment_Variables;
with RCL.DDS.Matching;
with RCL.Graph.Queries;

package body RCL.Graph is

   use Ada.Strings.Unbounded;
   use type Queries.Endpoint_Kind;

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


   -----------------------
   -- Endpoint USER_DATA --
   -----------------------

   function Endpoint_User_Data
     (Layout : GID_Layout; DDS_Type_Name : String; Extra : String := "") return String is
     (Extra & (if Layout = Jazzy_16
               then "typehash=" & ROSIDL.Type_Hashes.Hash_Of_DDS_Type (DDS_Type_Name) & ";"
               else ""));

   function Type_Hash (User_Data : String) return String is
      Value : constant String := RCL.DDS.Matching.User_Data_Value (User_Data, "typehash");
   begin
      return (if Value = "" then Zero_Type_Hash else Value);
   end Type_Hash;

   -------------
   -- Queries --
   -------------

   function ROS_Type_Name (DDS_Type_Name : String) return String is
     (Queries.Demangle_Type (DDS_Type_Name));

   package Info_Vectors is new Ada.Containers.Vectors (Positive, Topic_Info);

   function Topics return Topic_Info_Array is
      function "<" (L, R : Topic_Info) return Boolean is
        (L.Name < R.Name or else (L.Name = R.Name and then L.Type_Name < R.Type_Name));
      package Sorting is new Info_Vectors.Generic_Sorting;
      List : Info_Vectors.Vector;
   begin
      for E of Queries.Topic_Endpoints loop
         declare
            Found : Boolean := False;
         begin
            for T of List loop
               if T.Name = E.Topic_Name and then T.Type_Name = E.Type_Name then
                  case E.Kind is
                     when Queries.Publisher => T.Publishers := T.Publishers + 1;
                     when Queries.Subscription => T.Subscribers := T.Subscribers + 1;
                  end case;
                  Found := True;
                  exit;
               end if;
            end loop;
            if not Found then
               List.Append
                 (Topic_Info'(E.Topic_Name, E.Type_Name,
                              (if E.Kind = Queries.Publisher then 1 else 0),
                              (if E.Kind = Queries.Subscription then 1 else 0)));
            end if;
         end;
      end loop;
      Sorting.Sort (List);
      return Result : Topic_Info_Array (1 .. Natural (List.Length)) do
         for I in Result'Range loop
            Result (I) := List (I);
         end loop;
      end return;
   end Topics;

   function Count_Publishers (Topic : String) return Natural is
     (Queries.Count_Publishers (Topic));

   function Count_Subscribers (Topic : String) return Natural is
     (Queries.Count_Subscribers (Topic));

end RCL.Graph;
