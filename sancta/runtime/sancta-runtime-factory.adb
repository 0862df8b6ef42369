with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Strings.Unbounded;
with Sancta.Edit_Distances;

package body Sancta.Runtime.Factory is

   function Create_Component (Ctx : Components.Context) return Components.Component_Access is
      Result : constant Components.Component_Access := new Kind;
   begin
      Result.Initialize (Ctx);
      return Result;
   end Create_Component;

   use Ada.Strings.Unbounded;

   type Registration is record
      Info   : Components.Descriptor;
      Create : Creator;
   end record;

   package Registration_Maps is new Ada.Containers.Indefinite_Ordered_Maps
     (String, Registration);

   protected Registry is
      procedure Add (Info : Components.Descriptor; Create : Creator; Added : out Boolean);
      function Find (Name : String) return Registration;
      function Contains (Name : String) return Boolean;
      function All_Names return Local_Databases.Key_Vectors.Vector;
   private
      Map : Registration_Maps.Map;
   end Registry;

   protected body Registry is
      procedure Add (Info : Components.Descriptor; Create : Creator; Added : out Boolean) is
         Name : constant String := To_String (Info.Name);
      begin
         Added := not Map.Contains (Name);
         if Added then
            Map.Insert (Name, (Info, Create));
         end if;
      end Add;

      function Find (Name : String) return Registration is (Map (Name));

      function Contains (Name : String) return Boolean is (Map.Contains (Name));

      function All_Names return Local_Databases.Key_Vectors.Vector is
         Result : Local_Databases.Key_Vectors.Vector;
      begin
         for Position in Map.Iterate loop
            Result.Append (Registration_Maps.Key (Position));
         end loop;
         return Result;
      end All_Names;
   end Registry;

   procedure Register (Info : Components.Descriptor; Create : not null Creator) is
      Added : Boolean;
   begin
      Registry.Add (Info, Create, Added);
      if not Added then
         raise Program_Error with "component '" & To_String (Info.Name)
           & "' registered twice";
      end if;
   end Register;

   function Is_Registered (Name : String) return Boolean is (Registry.Contains (Name));

   function Description (Name : String) return Components.Descriptor is
     (Registry.Find (Name).Info);

   function Create (Name : String; Ctx : Components.Context) return Components.Component_Access
   is (Registry.Find (Name).Create (Ctx));

   function Names return Local_Databases.Key_Vectors.Vector is (Registry.All_Names);

   function Closest
     (Name : String; Candidates : Local_Databases.Key_Vectors.Vector) return String is
      Limit  : constant Natural := Natural'Max (2, Name'Length / 3);
      Result : Unbounded_String;
      Count  : Natural := 0;
      --  Each distance computed once (a megabyte name must not cost a
      --  distance per candidate per D); a length difference above Limit is
      --  a distance above Limit.
      Distance : array (1 .. Natural (Candidates.Length)) of Natural;
   begin
      for I in Distance'Range loop
         declare
            C : constant String := Candidates (I);
         begin
            Distance (I) :=
              (if abs (C'Length - Name'Length) > Limit then Limit + 1
               else Edit_Distances.Distance (Name, C, Ignore_Case => True));
         end;
      end loop;
      for D in 0 .. Limit loop
         exit when Count = 3;
         for I in Distance'Range loop
            if Count < 3 and then Distance (I) = D then
               if Count > 0 then
                  Append (Result, ", ");
               end if;
               Append (Result, "'" & Candidates (I) & "'");
               Count := Count + 1;
            end if;
         end loop;
      end loop;
      return To_String (Result);
   end Closest;

end Sancta.Runtime.Factory;
