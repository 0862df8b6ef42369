with Ada.Strings.Fixed;

package body RCL.Parameters.Stores is

   function Key (Node_Name, Name : String) return String is (Node_Name & ASCII.NUL & Name);

   function Matches (Pattern, Node_Name : String) return Boolean is
      Base : constant Natural := Ada.Strings.Fixed.Index (Node_Name, "/", Ada.Strings.Backward);
   begin
      return Pattern in "/**" | "**"
        or else Pattern = Node_Name
        or else Pattern = Node_Name (Base + 1 .. Node_Name'Last);
   end Matches;

   protected body Store is

      procedure Insert (Node_Name, Name : String; E : Entry_Record; Done : out Boolean) is
      begin
         Done := not Entries.Contains (Key (Node_Name, Name));
         if Done then
            Entries.Insert (Key (Node_Name, Name), E);
         end if;
      end Insert;

      function Contains (Node_Name, Name : String) return Boolean is
        (Entries.Contains (Key (Node_Name, Name)));

      function Get (Node_Name, Name : String) return Entry_Record is
        (Entries.Element (Key (Node_Name, Name)));

      procedure Put_Value (Node_Name, Name : String; V : Value) is
      begin
         Entries.Reference (Key (Node_Name, Name)).Current := V;
      end Put_Value;

      function Names_Of (Node_Name : String) return Text_Vectors.Vector is
         Prefix : constant String := Node_Name & ASCII.NUL;
      begin
         return R : Text_Vectors.Vector do
            for C in Entries.Iterate loop
               declare
                  K : constant String := Entry_Maps.Key (C);
               begin
                  if K'Length > Prefix'Length
                    and then K (K'First .. K'First + Prefix'Length - 1) = Prefix
                  then
                     R.Append (To_Unbounded_String (K (K'First + Prefix'Length .. K'Last)));
                  end if;
               end;
            end loop;
         end return;
      end Names_Of;

      procedure Set_Validator (Node_Name : String; Check : Validator) is
      begin
         Validators.Include (Node_Name, Check);
      end Set_Validator;

      function Validator_Of (Node_Name : String) return Validator is
        (if Validators.Contains (Node_Name) then Validators.Element (Node_Name) else null);

      procedure Set_Publisher (Node_Name : String; P : Publisher_Access) is
      begin
         Publishers.Include (Node_Name, P);
      end Set_Publisher;

      function Publisher_Of (Node_Name : String) return Publisher_Access is
        (if Publishers.Contains (Node_Name) then Publishers.Element (Node_Name) else null);

      procedure Add_Override (O : Override) is
      begin
         Overrides.Append (O);
      end Add_Override;

      procedure Clear_Overrides is
      begin
         Overrides.Clear;
      end Clear_Overrides;

      procedure Find_Override
        (Node_Name, Name : String; Found : out Boolean; O : out Override) is
      begin
         Found := False;
         for Each of Overrides loop
            if To_String (Each.Name) = Name
              and then Matches (To_String (Each.Pattern), Node_Name)
            then
               Found := True;
               O := Each;
            end if;
         end loop;
      end Find_Override;

      procedure Mark_Loaded (Was_Loaded : out Boolean) is
      begin
         Was_Loaded := Loaded;
         Loaded := True;
      end Mark_Loaded;

   end Store;

end RCL.Parameters.Stores;
