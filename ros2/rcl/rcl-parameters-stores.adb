with Ada.Strings.Fixed;

package body RCL.Parameters.Stores is

   function Key (Node_Name, Name : String) return String is (Node_Name & ASCII.NUL & Name);

   function Segments_Match (Pattern, Name : String) return Boolean is
      --  Pattern and Name: '/'-separated segments ("" or "/a/b"); in Pattern
      --  the segment "**" stands for any number of Name's segments (none
      --  too) and "*" for one.
      function Segment_End (S : String) return Natural is
        (if S = "" then S'Last
         else (declare Next : constant Natural :=
                 Ada.Strings.Fixed.Index (S (S'First + 1 .. S'Last), "/");
               begin (if Next = 0 then S'Last else Next - 1)));
      P_End : constant Natural := Segment_End (Pattern);
      N_End : constant Natural := Segment_End (Name);
   begin
      if Pattern = "" then
         return Name = "";
      elsif Pattern (Pattern'First .. P_End) = "/**" then
         return Segments_Match (Pattern (P_End + 1 .. Pattern'Last), Name)
           or else (Name /= ""
                    and then Segments_Match (Pattern, Name (N_End + 1 .. Name'Last)));
      elsif Name = "" then
         return False;
      else
         return (Pattern (Pattern'First .. P_End) = "/*"
                 or else Pattern (Pattern'First .. P_End) = Name (Name'First .. N_End))
           and then Segments_Match (Pattern (P_End + 1 .. Pattern'Last),
                                    Name (N_End + 1 .. Name'Last));
      end if;
   end Segments_Match;

   function Matches (Pattern, Node_Name : String) return Boolean is
      --  As rclcpp and rclpy: a name without a leading '/' is made absolute,
      --  so "talker" is "/talker", the node of that name in the root namespace.
      Absolute : constant String :=
        (if Pattern /= "" and then Pattern (Pattern'First) = '/' then Pattern else "/" & Pattern);
   begin
      return Absolute = "/**"
        or else Absolute = Node_Name
        or else Segments_Match (Absolute, Node_Name);
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
