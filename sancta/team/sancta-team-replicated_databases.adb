package body Sancta.Team.Replicated_Databases is

   use Runtime.Values;

   function Newer (Rev : Long_Long_Integer; Writer : String; Than : Meta) return Boolean is
     (Rev > Than.Revision
      or else (Rev = Than.Revision and then Writer > To_String (Than.Writer)));

   function State_Entry
     (Key : String; Item : Value'Class; Revision : Long_Long_Integer; Writer : String)
      return Networks.State_Entry is
     ((Key => To_Unbounded_String (Key), Value_Type => To_Unbounded_String (Item.Type_Name),
       Value => To_Unbounded_String (Item.Image), Revision => Revision,
       Writer => To_Unbounded_String (Writer)));
   --  Key's Item as the network carries it (its type's name and its image).

   protected body Store is
      procedure Write_Local
        (Key : String; Item : Value'Class; Self : String; Rev : out Long_Long_Integer)
      is
         M : Meta;
      begin
         if Map.Contains (Key) then
            M := Map.Element (Key);
         end if;
         M.Revision := M.Revision + 1;
         M.Writer := To_Unbounded_String (Self);
         M.Item := Holders.To_Holder (Item);
         Map.Include (Key, M);
         Rev := M.Revision;
      end Write_Local;

      procedure Offer
        (Key : String; Item : Value'Class; Rev : Long_Long_Integer; Writer : String;
         Accepted : out Boolean)
      is
         Old : Meta;
      begin
         if Map.Contains (Key) then
            Old := Map.Element (Key);
         end if;
         Accepted := Newer (Rev, Writer, Old);
         if Accepted then
            Map.Include (Key, (Rev, To_Unbounded_String (Writer), Holders.To_Holder (Item)));
         end if;
      end Offer;

      function Find (Key : String) return Meta is
        (if Map.Contains (Key) then Map.Element (Key) else (others => <>));

      function Snapshot return Meta_Maps.Map is (Map);
   end Store;

   procedure Settle (This : in out Team_Database; Key : String; Item : Value'Class) is
   begin
      This.Replica.Put (Key, Item);
      --  Another task may have stored a newer entry between the decision
      --  and the local store: the replica ends with the winner.
      declare
         Now : constant Meta := This.Data.Find (Key);
      begin
         if not Now.Item.Is_Empty and then Now.Item.Element /= Item then
            This.Replica.Put (Key, Now.Item.Element);
         end if;
      end;
   end Settle;

   procedure Attach (This : in out Team_Database) is
   begin
      This.Net.Set_State_Consumer (This'Unchecked_Access);
      This.Net.Add_Membership_Listener (This'Unchecked_Access);
   end Attach;

   function Contains (This : Team_Database; Key : String) return Boolean is
     (not This.Data.Find (Key).Item.Is_Empty);

   function Get (This : Team_Database; Key : String) return Value'Class is
     (This.Data.Find (Key).Item.Element);

   function Revision (This : Team_Database; Key : String) return Long_Long_Integer is
     (This.Data.Find (Key).Revision);

   function Writer (This : Team_Database; Key : String) return String is
     (To_String (This.Data.Find (Key).Writer));

   procedure Put (This : in out Team_Database; Key : String; Item : Value'Class) is
      Rev : Long_Long_Integer;
   begin
      This.Data.Write_Local (Key, Item, This.Net.Id, Rev);
      This.Net.Publish_State (State_Entry (Key, Item, Rev, This.Net.Id));
      Settle (This, Key, Item);
   end Put;

   procedure Put (This : in out Team_Database; Key : String; Text : String) is
   begin
      This.Put (Key, To_Value (Text));
   end Put;

   function Get_String (This : Team_Database; Key : String) return String is
      M : constant Meta := This.Data.Find (Key);
   begin
      return (if M.Item.Is_Empty then "" else M.Item.Element.Image);
   end Get_String;

   procedure Update
     (This    : in out Team_Database;
      Key     : String;
      Process : not null access procedure (Item : in out Value'Class))
   is
      Item : Holders.Holder := This.Data.Find (Key).Item;
   begin
      Process (Item.Reference);
      This.Put (Key, Item.Element);
   end Update;

   procedure Listen
     (This : in out Team_Database; Key : String; Observer : not null Listener_Access) is
   begin
      This.Replica.Listen (Key, Observer);
   end Listen;

   procedure Unlisten
     (This : in out Team_Database; Key : String; Observer : not null Listener_Access) is
   begin
      This.Replica.Unlisten (Key, Observer);
   end Unlisten;

   function Keys (This : Team_Database) return Runtime.Local_Databases.Key_Vectors.Vector is
     (This.Keys_With_Prefix (""));

   function Keys_With_Prefix
     (This : Team_Database; Prefix : String) return Runtime.Local_Databases.Key_Vectors.Vector
   is
      Map : constant Meta_Maps.Map := This.Data.Snapshot;
   begin
      return Result : Runtime.Local_Databases.Key_Vectors.Vector do
         for C in Map.Iterate loop
            declare
               K : constant String := Meta_Maps.Key (C);
            begin
               if K'Length >= Prefix'Length
                 and then K (K'First .. K'First + Prefix'Length - 1) = Prefix
               then
                  Result.Append (K);
               end if;
            end;
         end loop;
      end return;
   end Keys_With_Prefix;

   function Digest (This : Team_Database) return String is
      Map    : constant Meta_Maps.Map := This.Data.Snapshot;
      Result : Unbounded_String;
   begin
      for C in Map.Iterate loop
         declare
            M : constant Meta := Meta_Maps.Element (C);
         begin
            Append (Result, Meta_Maps.Key (C) & "#" & M.Revision'Image & "@"
                    & To_String (M.Writer) & "=" & M.Item.Element.Image & ASCII.LF);
         end;
      end loop;
      return To_String (Result);
   end Digest;

   procedure Republish (This : in out Team_Database'Class; Joined : Name_Sets.Set) is
      Map  : constant Meta_Maps.Map := This.Data.Snapshot;
      Self : constant String := This.Net.Id;
      Sent : Natural := 0;
   begin
      for C in Map.Iterate loop
         declare
            M      : constant Meta := Meta_Maps.Element (C);
            Writer : constant String := To_String (M.Writer);
         begin
            if Writer = Self or else Joined.Contains (Writer)
              or else not This.Net.Is_Member (Writer)
            then
               This.Net.Publish_State
                 (State_Entry (Meta_Maps.Key (C), M.Item.Element, M.Revision, Writer));
               Sent := Sent + 1;
            end if;
         end;
      end loop;
      This.Republished.Add (Sent);
   end Republish;

   procedure Resynchronise (This : in out Team_Database; Joined : String := "") is
   begin
      Republish (This, (if Joined = "" then Name_Sets.Empty_Set
                        else Name_Sets.To_Set (Joined)));
   end Resynchronise;

   overriding procedure On_State (This : in out Team_Database; Item : Networks.State_Entry) is
      Key      : constant String := To_String (Item.Key);
      Decoded  : constant Runtime.Values.Value'Class :=
        Decode (To_String (Item.Value_Type), To_String (Item.Value));
      Accepted : Boolean;
   begin
      This.Data.Offer (Key, Decoded, Item.Revision, To_String (Item.Writer), Accepted);
      if Accepted then
         Settle (This, Key, Decoded);
      end if;
   end On_State;

   overriding procedure On_Joined (This : in out Team_Database; Member : String) is
      use type Ada.Real_Time.Time;
   begin
      if Member /= This.Net.Id then
         This.Resynchronise (Joined => Member);
         This.Catch_Up_At.Set
           (Ada.Real_Time.Clock + Ada.Real_Time.To_Time_Span (Catch_Up_Delay), Member);
      end if;
   end On_Joined;

   protected body Due_Time is
      procedure Set (At_Time : Ada.Real_Time.Time; Member : String) is
      begin
         When_Due := At_Time;
         Members.Include (Member);
      end Set;

      procedure Take (Now : Ada.Real_Time.Time; Due : out Boolean; Joined : out Name_Sets.Set) is
         use type Ada.Real_Time.Time;
      begin
         Due := When_Due /= Ada.Real_Time.Time_Last and then Now >= When_Due;
         Joined := Name_Sets.Empty_Set;
         if Due then
            When_Due := Ada.Real_Time.Time_Last;
            Joined := Members;
            Members.Clear;
         end if;
      end Take;
   end Due_Time;

   protected body Tally is
      procedure Add (N : Natural) is
      begin
         Total := Total + Long_Long_Integer (N);
      end Add;
      function Value return Long_Long_Integer is (Total);
   end Tally;

   function Republished_Count (This : Team_Database) return Long_Long_Integer is
     (This.Republished.Value);

   procedure Catch_Up (This : in out Team_Database) is
      Due    : Boolean;
      Joined : Name_Sets.Set;
   begin
      This.Catch_Up_At.Take (Ada.Real_Time.Clock, Due, Joined);
      if Due then
         Republish (This, Joined);
      end if;
   end Catch_Up;

   function Decode (Type_Name, Text : String) return Value'Class is
      --  Values from other nodes: a value that does not parse as its
      --  declared type, or of a type unknown here, is refused (the network
      --  drops the entry and says so).
      Bad : constant String :=
        "value " & (if Text'Length > 40 then Text (Text'First .. Text'First + 39) & "..."
                    else Text) & " is not a valid " & Type_Name;
   begin
      if Type_Name = "types.integer" then
         return Integer_Value'(Data => Long_Long_Integer'Value (Text));
      elsif Type_Name = "types.real" then
         declare
            X : constant Long_Float := Long_Float'Value (Text);
         begin
            if not X'Valid then
               raise Networks.Malformed_Data with Bad;
            end if;
            return Real_Value'(Data => X);
         end;
      elsif Type_Name = "types.boolean" then
         if Text not in "true" | "false" then
            raise Networks.Malformed_Data with Bad;
         end if;
         return Boolean_Value'(Data => Text = "true");
      elsif Runtime.Values.Is_Known_Type (Type_Name) then
         return To_Value (Text);
      else
         raise Networks.Malformed_Data with "unknown value type " & Type_Name;
      end if;
   exception
      when Constraint_Error =>
         raise Networks.Malformed_Data with Bad;
   end Decode;

end Sancta.Team.Replicated_Databases;
