with Sancta.Runtime.Configurations.Loading;
with Sancta.Runtime.Factory;

package body Sancta.Runtime.Configurations is

   function Image (D : Diagnostic) return String is
     (XML_Trees.Image (D.Where) & ": " & (if D.Level = Error then "error" else "warning")
      & ": " & To_String (D.Message));

   procedure Report
     (Result : in out Configuration; Level : Severity; Where : Position; Message : String) is
   begin
      Result.Diagnostics.Append
        (Diagnostic'(Level => Level, Where => Where, Message => To_Unbounded_String (Message)));
   end Report;

   function Trim (N : Integer) return String is
      S : constant String := N'Image;
   begin
      return (if N < 0 then S else S (S'First + 1 .. S'Last));
   end Trim;

   function Suggest
     (Name : String; Candidates : Local_Databases.Key_Vectors.Vector) return String is
      Near : constant String := Factory.Closest (Name, Candidates);
   begin
      return (if Near = "" then "" else " (did you mean " & Near & "?)");
   end Suggest;

   procedure Load
     (File      : String;
      Result    : out Configuration;
      Overrides : String_Map := Components.String_Maps.Empty_Map) is
   begin
      Loading.Load (File, Result, Overrides);
   end Load;

   function Count (This : Configuration; Level : Severity) return Natural is
      Result : Natural := 0;
   begin
      for D of This.Diagnostics loop
         if D.Level = Level then
            Result := Result + 1;
         end if;
      end loop;
      return Result;
   end Count;

   function Error_Count (This : Configuration) return Natural is (Count (This, Error));

   function Warning_Count (This : Configuration) return Natural is (Count (This, Warning));

   function Find_Agent (This : Configuration; Id : String) return Natural is
   begin
      for I in This.Agents.First_Index .. This.Agents.Last_Index loop
         if This.Agents (I).Id = Id then
            return I;
         end if;
      end loop;
      return 0;
   end Find_Agent;

   function Agent_Ids (This : Configuration) return String is
      Result : Unbounded_String;
   begin
      for A of This.Agents loop
         if Length (Result) > 0 then
            Append (Result, ", ");
         end if;
         Append (Result, A.Id);
      end loop;
      return To_String (Result);
   end Agent_Ids;

end Sancta.Runtime.Configurations;
