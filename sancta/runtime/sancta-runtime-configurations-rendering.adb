with Ada.Containers.Indefinite_Ordered_Maps;

package body Sancta.Runtime.Configurations.Rendering is

   use type Components.Port_Direction;

   function Pad (S : String; Width : Natural) return String is
     (if S'Length >= Width then S else S & [1 .. Width - S'Length => ' ']);

   function Wiring_Table (This : Configuration) return String is
      LF     : constant Character := ASCII.LF;
      Result : Unbounded_String;
   begin
      for A of This.Agents loop
         Append (Result, "agent " & To_String (A.Id)
                 & (if Length (A.Kind) > 0 then " (" & To_String (A.Kind) & ")" else "") & LF);
         Append (Result, "  components (start order):" & LF);
         for I of A.Instances loop
            Append (Result, "    " & Pad (To_String (I.Name), 24) & " order " & Trim (I.Order)
                    & (if I.Enabled then "" else "  (disabled)") & LF);
         end loop;
         Append (Result, "  " & Pad ("key", 26) & Pad ("type", 16) & Pad ("provider", 32)
                 & "consumers" & LF);
         declare
            package Key_Sets is new Ada.Containers.Indefinite_Ordered_Maps (String, Boolean);
            Keys : Key_Sets.Map;
         begin
            for I of A.Instances loop
               if I.Enabled then
                  for B of I.Bindings loop
                     Keys.Include (To_String (B.Key), True);
                  end loop;
               end if;
            end loop;
            for K in Keys.Iterate loop
               declare
                  Key       : constant String := Key_Sets.Key (K);
                  Provider  : Unbounded_String := To_Unbounded_String ("-");
                  Consumers : Unbounded_String;
                  Type_Name : Unbounded_String;
               begin
                  for I of A.Instances loop
                     if I.Enabled then
                        for B of I.Bindings loop
                           if B.Key = Key then
                              if B.Direction = Components.Output then
                                 Provider := I.Name & "." & B.Data;
                                 Type_Name := B.Type_Name;
                              else
                                 if Length (Consumers) > 0 then
                                    Append (Consumers, ", ");
                                 end if;
                                 Append (Consumers, I.Name & "." & B.Data);
                                 if Length (Type_Name) = 0 then
                                    Type_Name := B.Type_Name;
                                 end if;
                              end if;
                           end if;
                        end loop;
                     end if;
                  end loop;
                  Append (Result, "  " & Pad (Key, 26) & Pad (To_String (Type_Name), 16)
                          & Pad (To_String (Provider), 32)
                          & (if Length (Consumers) = 0 then "-" else To_String (Consumers))
                          & LF);
               end;
            end loop;
         end;
      end loop;
      return To_String (Result);
   end Wiring_Table;

   function Dot_Id (Agent_Id, Name : String) return String is
      Result : String := Agent_Id & "_" & Name;
   begin
      for C of Result loop
         if not Is_Identifier_Char (C) then
            C := '_';
         end if;
      end loop;
      return "n_" & Result;
   end Dot_Id;

   function Escape (S : String) return String is
      Result : Unbounded_String;
   begin
      for C of S loop
         if C = '"' or else C = '\' then
            Append (Result, '\');
         end if;
         Append (Result, C);
      end loop;
      return To_String (Result);
   end Escape;

   function Quote (S : String) return String is ("""" & Escape (S) & """");

   function To_Dot (This : Configuration) return String is
      LF     : constant Character := ASCII.LF;
      Result : Unbounded_String;
      Index  : Natural := 0;
   begin
      Append (Result, "digraph " & Quote (To_String (This.Name)) & " {" & LF
              & "  rankdir=LR;" & LF & "  node [shape=box, style=rounded];" & LF);
      for A of This.Agents loop
         Index := Index + 1;
         Append (Result, "  subgraph cluster_" & Trim (Index) & " {" & LF
                 & "    label=" & Quote ("agent " & To_String (A.Id)
                   & (if Length (A.Kind) > 0 then " (" & To_String (A.Kind) & ")" else ""))
                 & ";" & LF);
         for I of A.Instances loop
            if I.Enabled then
               Append (Result, "    " & Dot_Id (To_String (A.Id), To_String (I.Name))
                       & " [label=" & Quote (To_String (I.Name)) & "];" & LF);
            end if;
         end loop;
         for P of A.Instances loop
            if P.Enabled then
               for Out_B of P.Bindings loop
                  if Out_B.Direction = Components.Output then
                     for C of A.Instances loop
                        if C.Enabled then
                           for In_B of C.Bindings loop
                              if In_B.Direction = Components.Input and then In_B.Key = Out_B.Key
                              then
                                 Append (Result, "    "
                                         & Dot_Id (To_String (A.Id), To_String (P.Name))
                                         & " -> "
                                         & Dot_Id (To_String (A.Id), To_String (C.Name))
                                         & " [label=""" & Escape (To_String (Out_B.Key))
                                         & "\n" & Escape (To_String (Out_B.Type_Name))
                                         & """];" & LF);
                              end if;
                           end loop;
                        end if;
                     end loop;
                  end if;
               end loop;
            end if;
         end loop;
         Append (Result, "  }" & LF);
      end loop;
      Append (Result, "}" & LF);
      return To_String (Result);
   end To_Dot;

end Sancta.Runtime.Configurations.Rendering;
