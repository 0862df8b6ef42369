with Ada.Containers.Indefinite_Ordered_Maps;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Factory;
with Sancta.Runtime.Values;

package body Sancta.Runtime.Configurations.Wiring is

   use type Components.Port_Direction;
   use XML_Trees;

   procedure Propagate_Types (Result : in out Configuration; A : in out Agent) is
      --  Untyped outputs of components that follow their inputs take the
      --  type of what feeds them, repeatedly (chains of copies).

      function Provided_Type (Key : Unbounded_String) return String is
      begin
         for I of A.Instances loop
            if I.Enabled then
               for B of I.Bindings loop
                  if B.Direction = Components.Output and then B.Key = Key then
                     return To_String (B.Type_Name);
                  end if;
               end loop;
            end if;
         end loop;
         return "";
      end Provided_Type;

      procedure Common_Type
        (I : Instance; Common : out Unbounded_String; Conflict : out Boolean) is
      begin
         Common := Null_Unbounded_String;
         Conflict := False;
         for B of I.Bindings loop
            if B.Direction = Components.Input and then B.Any_Port then
               declare
                  T : constant String :=
                    (if To_String (B.Type_Name) /= Values.Any_Type then To_String (B.Type_Name)
                     else Provided_Type (B.Key));
               begin
                  if T /= "" and then T /= Values.Any_Type then
                     if Length (Common) = 0 then
                        Common := To_Unbounded_String (T);
                     elsif Common /= T then
                        Conflict := True;
                     end if;
                  end if;
               end;
            end if;
         end loop;
      end Common_Type;

      Changed : Boolean := True;
      Rounds  : Natural := 0;
   begin
      while Changed and then Rounds <= Natural (A.Instances.Length) loop
         Changed := False;
         Rounds := Rounds + 1;
         for Index in A.Instances.First_Index .. A.Instances.Last_Index loop
            declare
               I        : Instance := A.Instances (Index);
               Common   : Unbounded_String;
               Conflict : Boolean;
            begin
               if I.Enabled and then Factory.Description (To_String (I.Component)).Follows_Inputs
               then
                  Common_Type (I, Common, Conflict);
                  if Length (Common) > 0 and then not Conflict then
                     for B of I.Bindings loop
                        if B.Direction = Components.Output and then B.Any_Port
                          and then To_String (B.Type_Name) = Values.Any_Type
                        then
                           B.Type_Name := Common;
                           Changed := True;
                        end if;
                     end loop;
                     A.Instances.Replace_Element (Index, I);
                  end if;
               end if;
            end;
         end loop;
      end loop;
      for I of A.Instances loop
         if I.Enabled and then Factory.Description (To_String (I.Component)).Follows_Inputs then
            declare
               Common   : Unbounded_String;
               Conflict : Boolean;
            begin
               Common_Type (I, Common, Conflict);
               if Conflict then
                  Report (Result, Warning, I.Where,
                          "the inputs of " & To_String (I.Name) & " are of different types: "
                          & "its output is left untyped (any)");
               end if;
            end;
         end if;
      end loop;
   end Propagate_Types;

   procedure For_Each_Binding
     (A         : Agent;
      Direction : Components.Port_Direction;
      Process   : not null access procedure (I : Instance; B : Binding; Key : String)) is
      --  Process for each binding of that direction of A's enabled
      --  instances, in order, with the binding's database key.
   begin
      for I of A.Instances loop
         if I.Enabled then
            for B of I.Bindings loop
               if B.Direction = Direction then
                  Process (I, B, To_String (B.Key));
               end if;
            end loop;
         end if;
      end loop;
   end For_Each_Binding;

   procedure Wire (Result : in out Configuration; A : Agent) is
      type Provider is record
         Instance_Name : Unbounded_String;
         Type_Name     : Unbounded_String;
         Where         : Position;
         Used          : Boolean := False;
      end record;
      package Provider_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, Provider);
      Providers : Provider_Maps.Map;

      function Provided_Keys return Local_Databases.Key_Vectors.Vector is
         Result : Local_Databases.Key_Vectors.Vector;
      begin
         for C in Providers.Iterate loop
            Result.Append (Provider_Maps.Key (C));
         end loop;
         return Result;
      end Provided_Keys;

      procedure Provide (I : Instance; B : Binding; Key : String) is
      begin
         if Providers.Contains (Key) then
            Report (Result, Error, B.Where,
                    "'" & Key & "' is provided twice in agent '" & To_String (A.Id)
                    & "': by " & To_String (I.Name) & " and by "
                    & To_String (Providers (Key).Instance_Name) & " (at "
                    & Image (Providers (Key).Where) & ")");
         else
            Providers.Insert (Key, (I.Name, B.Type_Name, B.Where, False));
         end if;
      end Provide;

      procedure Require (I : Instance; B : Binding; Key : String) is
      begin
         if not Providers.Contains (Key) then
            Report (Result, (if B.Optional then Warning else Error), B.Where,
                    (if B.Optional then "optional input '" else "input '")
                    & To_String (B.Data) & "' of " & To_String (I.Name)
                    & " requires '" & Key & "', which no enabled component of agent '"
                    & To_String (A.Id) & "' provides"
                    & Suggest (Key, Provided_Keys));
         else
            Providers (Key).Used := True;
            if not Values.Compatible (To_String (Providers (Key).Type_Name),
                                      To_String (B.Type_Name))
            then
               Report (Result, Error, B.Where,
                       "type mismatch on '" & Key & "': " & To_String (I.Name)
                       & " requires " & To_String (B.Type_Name) & " but "
                       & To_String (Providers (Key).Instance_Name) & " provides "
                       & To_String (Providers (Key).Type_Name) & " (at "
                       & Image (Providers (Key).Where) & ")");
            end if;
         end if;
      end Require;

   begin
      For_Each_Binding (A, Components.Output, Provide'Access);
      For_Each_Binding (A, Components.Input, Require'Access);
      --  Forwarding loops: copy, merge and switch pass each input on at
      --  once, so a cycle of them would circulate a value forever.
      declare
         function Is_Forwarder (I : Instance) return Boolean is
           (I.Enabled and then To_String (I.Component) in "copy" | "merge" | "switch");

         function Index_Of (Name : Unbounded_String) return Natural is
         begin
            for K in A.Instances.First_Index .. A.Instances.Last_Index loop
               if A.Instances (K).Name = Name then
                  return K;
               end if;
            end loop;
            return 0;
         end Index_Of;

         function Reaches (From, Target : Positive; Depth : Natural) return Boolean is
            --  True when Target feeds From through forwarders only.
         begin
            if Depth > Natural (A.Instances.Length) then
               return False;
            end if;
            for B of A.Instances (From).Bindings loop
               if B.Direction = Components.Input
                 and then Providers.Contains (To_String (B.Key))
               then
                  declare
                     P : constant Natural :=
                       Index_Of (Providers (To_String (B.Key)).Instance_Name);
                  begin
                     if P = Target then
                        return True;
                     elsif P /= 0 and then Is_Forwarder (A.Instances (P))
                       and then Reaches (P, Target, Depth + 1)
                     then
                        return True;
                     end if;
                  end;
               end if;
            end loop;
            return False;
         end Reaches;
      begin
         for K in A.Instances.First_Index .. A.Instances.Last_Index loop
            if Is_Forwarder (A.Instances (K)) and then Reaches (K, K, 0) then
               Report (Result, Error, A.Instances (K).Where,
                       "forwarding loop: the output of " & To_String (A.Instances (K).Name)
                       & " comes back to its input through copy/merge/switch only"
                       & " (a value would circulate forever)");
               exit;
            end if;
         end loop;
      end;
      for P in Providers.Iterate loop
         if not Provider_Maps.Element (P).Used then
            Report (Result, Warning, Provider_Maps.Element (P).Where,
                    "output '" & Provider_Maps.Key (P) & "' of "
                    & To_String (Provider_Maps.Element (P).Instance_Name)
                    & " is not used by any component of agent '" & To_String (A.Id) & "'");
         end if;
      end loop;
   end Wire;

end Sancta.Runtime.Configurations.Wiring;
