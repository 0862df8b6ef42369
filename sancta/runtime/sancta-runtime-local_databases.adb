with Ada.Exceptions;
with Ada.Strings.Unbounded;
with Ada.Task_Attributes;
with Sancta.Logging;
with System;

package body Sancta.Runtime.Local_Databases is

   use Ada.Strings.Unbounded;
   use type System.Address;

   --  The keys whose listeners are running in the current task, outermost
   --  first, for the detection of recursion. Allocated at the first
   --  notification made by a task and kept for the task's life (a small
   --  record per notifying task; freeing it at each notification halved the
   --  put rate with listeners).

   type Link is record
      Owner : System.Address;
      Key   : Unbounded_String;
   end record;

   package Link_Vectors is new Ada.Containers.Vectors (Positive, Link);

   type Chain is record
      Links : Link_Vectors.Vector;
   end record;
   type Chain_Access is access Chain;

   package Chains is new Ada.Task_Attributes (Chain_Access, null);

   Max_Depth : constant := 64;
   --  Notification chains deeper than this are reported as recursion too.

   function Chain_Image (C : Chain; Last : String) return String is
      Result : Unbounded_String;
   begin
      for L of C.Links loop
         Append (Result, L.Key);
         Append (Result, " -> ");
      end loop;
      return To_String (Result) & Last;
   end Chain_Image;

   procedure Check_Recursion (This : Database; Key : String) is
      C : constant Chain_Access := Chains.Value;
   begin
      if C = null or else C.Links.Is_Empty then
         return;
      end if;
      for L of C.Links loop
         if L.Owner = This'Address and then L.Key = Key then
            raise Listener_Recursion with "listener recursion: " & Chain_Image (C.all, Key);
         end if;
      end loop;
      if Natural (C.Links.Length) >= Max_Depth then
         raise Listener_Recursion with "listener chain deeper than" & Max_Depth'Image & ": "
           & Chain_Image (C.all, Key);
      end if;
   end Check_Recursion;

   procedure Notify
     (This : Database; Key : String; Item : Value'Class; Observers : Listener_Vectors.Vector)
   is
      C : Chain_Access := Chains.Value;

      procedure Pop is
      begin
         C.Links.Delete_Last;
      end Pop;

   begin
      if C = null then
         C := new Chain;
         Chains.Set_Value (C);
      end if;
      C.Links.Append (Link'(This'Address, To_Unbounded_String (Key)));
      for Observer of Observers loop
         begin
            Observer.On_Key_Stored (Key, Item);
         exception
            when Listener_Recursion =>
               Pop;
               raise;
            when E : others =>
               Logging.Log ("database", Logging.Error,
                            "listener " & Observer.Listener_Name & " of key '" & Key
                            & "' failed: " & Ada.Exceptions.Exception_Information (E));
         end;
      end loop;
      Pop;
   end Notify;

   protected body Store is

      function Contains (Key : String) return Boolean is (Map.Contains (Key));

      function Get (Key : String) return Holders.Holder is
         Position : constant Entry_Maps.Cursor := Map.Find (Key);
      begin
         if Entry_Maps.Has_Element (Position) then
            return Map (Position).Item;
         else
            return Holders.Empty_Holder;
         end if;
      end Get;

      function Revision (Key : String) return Natural is
         Position : constant Entry_Maps.Cursor := Map.Find (Key);
      begin
         return (if Entry_Maps.Has_Element (Position) then Map (Position).Revision else 0);
      end Revision;

      procedure Find_Or_Add (Key : String; Position : out Entry_Maps.Cursor) is
         --  Key's entry; a new one (revision 0, no item, no observer) if
         --  the key is not in the map yet.
         Inserted : Boolean;
      begin
         Position := Map.Find (Key);
         if not Entry_Maps.Has_Element (Position) then
            Map.Insert (Key, (others => <>), Position, Inserted);
         end if;
      end Find_Or_Add;

      procedure Store_Item (Key : String; Item : Value'Class;
                            Observers : out Listener_Vectors.Vector) is
         Position : Entry_Maps.Cursor;
      begin
         Find_Or_Add (Key, Position);
         declare
            E : Entry_Record renames Map (Position);
         begin
            E.Item.Replace_Element (Item);
            E.Revision := E.Revision + 1;
            Observers := E.Observers;
         end;
         Count := Count + 1;
      end Store_Item;

      procedure Put
        (Key : String; Item : Value'Class; Observers : out Listener_Vectors.Vector) is
      begin
         Store_Item (Key, Item, Observers);
      end Put;

      procedure Put_If
        (Key       : String;
         Item      : Value'Class;
         Expected  : Natural;
         Done      : out Boolean;
         Observers : out Listener_Vectors.Vector) is
      begin
         Done := Revision (Key) = Expected;
         if Done then
            Store_Item (Key, Item, Observers);
         else
            Observers := Listener_Vectors.Empty_Vector;
         end if;
      end Put_If;

      procedure Listen (Key : String; Observer : Listener_Access) is
         Position : Entry_Maps.Cursor;
      begin
         --  A key with listeners but no value yet: revision 0, empty item.
         Find_Or_Add (Key, Position);
         if not Map (Position).Observers.Contains (Observer) then
            Map (Position).Observers.Append (Observer);
         end if;
      end Listen;

      procedure Unlisten (Key : String; Observer : Listener_Access) is
         Position : constant Entry_Maps.Cursor := Map.Find (Key);
      begin
         if Entry_Maps.Has_Element (Position) then
            declare
               Index : constant Natural := Map (Position).Observers.Find_Index (Observer);
            begin
               if Index /= Listener_Vectors.No_Index then
                  Map (Position).Observers.Delete (Index);
               end if;
            end;
         end if;
      end Unlisten;

      procedure Unlisten_All (Observer : Listener_Access) is
      begin
         for E of Map loop
            declare
               Index : constant Natural := E.Observers.Find_Index (Observer);
            begin
               if Index /= Listener_Vectors.No_Index then
                  E.Observers.Delete (Index);
               end if;
            end;
         end loop;
      end Unlisten_All;

      function Keys return Key_Vectors.Vector is
         Result : Key_Vectors.Vector;
      begin
         for Position in Map.Iterate loop
            if not Map (Position).Item.Is_Empty then
               Result.Append (Entry_Maps.Key (Position));
            end if;
         end loop;
         return Result;
      end Keys;

      function Stores return Long_Long_Integer is (Count);

   end Store;

   function Contains (This : Database; Key : String) return Boolean is
     (This.Data.Revision (Key) > 0);

   function Get (This : Database; Key : String) return Value'Class is
      Item : constant Holders.Holder := This.Data.Get (Key);
   begin
      if Item.Is_Empty then
         raise Unknown_Key with "no value under key '" & Key & "'";
      end if;
      return Item.Element;
   end Get;

   function Revision (This : Database; Key : String) return Natural is
     (This.Data.Revision (Key));

   procedure Put (This : in out Database; Key : String; Item : Value'Class) is
      Observers : Listener_Vectors.Vector;
   begin
      Check_Recursion (This, Key);
      This.Data.Put (Key, Item, Observers);
      if not Observers.Is_Empty then
         Notify (This, Key, Item, Observers);
      end if;
   end Put;

   procedure Update
     (This    : in out Database;
      Key     : String;
      Process : not null access procedure (Item : in out Value'Class))
   is
      Observers : Listener_Vectors.Vector;
      Done      : Boolean := False;
   begin
      Check_Recursion (This, Key);
      loop
         declare
            Seen    : constant Natural := This.Data.Revision (Key);
            Current : constant Holders.Holder := This.Data.Get (Key);
         begin
            if Seen = 0 or else Current.Is_Empty then
               raise Unknown_Key with "update of key '" & Key & "' that holds no value";
            end if;
            declare
               Copy : Value'Class := Current.Element;
            begin
               Process (Copy);
               This.Data.Put_If (Key, Copy, Seen, Done, Observers);
               if Done then
                  if not Observers.Is_Empty then
                     Notify (This, Key, Copy, Observers);
                  end if;
                  return;
               end if;
            end;
         end;
      end loop;
   end Update;

   procedure Listen (This : in out Database; Key : String; Observer : not null Listener_Access) is
   begin
      This.Data.Listen (Key, Observer);
   end Listen;

   procedure Unlisten (This : in out Database; Key : String; Observer : not null Listener_Access)
   is
   begin
      This.Data.Unlisten (Key, Observer);
   end Unlisten;

   procedure Unlisten_All (This : in out Database; Observer : not null Listener_Access) is
   begin
      This.Data.Unlisten_All (Observer);
   end Unlisten_All;

   function Keys (This : Database) return Key_Vectors.Vector is (This.Data.Keys);

   function Stores (This : Database) return Long_Long_Integer is (This.Data.Stores);

end Sancta.Runtime.Local_Databases;
