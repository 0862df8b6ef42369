--  The local database: a task-safe map from keys (external names of the
--  configuration) to values of any type derived from Values.Value, with
--  observers. Components communicate through it.
--
--     DB.Put ("odometric_pose", Values.Pose_Value'(Data => P));
--     DB.Listen ("odometric_pose", My_Listener'Access);
--     DB.Update ("counter", Increment'Access);   --  atomic read-modify-write
--
--  Design rules:
--  * The store is a protected object; Get, Put and Contains are atomic.
--  * Listeners are NEVER called from inside the protected object: Put stores
--    the value, takes a snapshot of the key's listeners and calls them
--    afterwards in the writer's task. With several writer tasks a listener
--    may be called concurrently, and two concurrent Puts of one key may be
--    notified in either order (each notification carries the value of its
--    own Put, and the database keeps the last one stored).
--  * Update runs its functor outside the protected object too, on a copy,
--    and stores the result only if nobody stored the key meanwhile (compare
--    by revision); otherwise it retries on the newer value. Concurrent
--    Updates therefore never lose one another's changes.
--  * Recursion: a listener that (directly or through other listeners) puts
--    into a key whose listeners are running in the same task raises
--    Listener_Recursion, naming the chain of keys; the value is not stored.
--  * A listener raising any other exception is logged (section "database")
--    with the listener's name; the other listeners still run.
with Ada.Containers.Indefinite_Holders;
with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Containers.Vectors;
with Ada.Strings.Hash;
with Sancta.Runtime.Values;

package Sancta.Runtime.Local_Databases is

   subtype Value is Values.Value;

   type Listener is limited interface;
   type Listener_Access is access all Listener'Class;

   procedure On_Key_Stored
     (This : in out Listener; Key : String; Value : Values.Value'Class) is abstract;
   --  Called after Value was stored under Key (outside the store's lock).

   function Listener_Name (This : Listener) return String is abstract;
   --  Names the listener in diagnostics.

   type Database is tagged limited private;
   type Database_Access is access all Database;

   function Contains (This : Database; Key : String) return Boolean;

   function Get (This : Database; Key : String) return Value'Class;
   --  Raises Unknown_Key when Key holds no value.

   function Revision (This : Database; Key : String) return Natural;
   --  How many times Key was stored (0 when it holds no value).

   procedure Put (This : in out Database; Key : String; Item : Value'Class);
   --  Store Item under Key, then call the key's listeners.

   procedure Update
     (This    : in out Database;
      Key     : String;
      Process : not null access procedure (Item : in out Value'Class));
   --  Atomic read-modify-write of Key's value (raises Unknown_Key when
   --  absent). Process may be called more than once under contention; it
   --  must not change the value's tag (Constraint_Error otherwise).

   procedure Listen (This : in out Database; Key : String; Observer : not null Listener_Access);
   --  Observer.On_Key_Stored will be called after each store of Key. Adding
   --  the same observer twice to one key has no effect.

   procedure Unlisten (This : in out Database; Key : String; Observer : not null Listener_Access);

   procedure Unlisten_All (This : in out Database; Observer : not null Listener_Access);
   --  Remove Observer from every key (a stopping component calls this).

   package Key_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   function Keys (This : Database) return Key_Vectors.Vector;
   --  Every key holding a value, in no particular order.

   function Stores (This : Database) return Long_Long_Integer;
   --  Total number of stores so far (statistics).

private

   package Holders is new Ada.Containers.Indefinite_Holders
     (Value'Class, Values."=");

   package Listener_Vectors is new Ada.Containers.Vectors (Positive, Listener_Access);

   type Entry_Record is record
      Item      : Holders.Holder;
      Revision  : Natural := 0;
      Observers : Listener_Vectors.Vector;
   end record;

   package Entry_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (Key_Type => String, Element_Type => Entry_Record, Hash => Ada.Strings.Hash,
      Equivalent_Keys => "=");

   protected type Store is
      function Contains (Key : String) return Boolean;
      function Get (Key : String) return Holders.Holder;
      --  Empty holder when absent.
      function Revision (Key : String) return Natural;
      procedure Put
        (Key : String; Item : Value'Class; Observers : out Listener_Vectors.Vector);
      procedure Put_If
        (Key       : String;
         Item      : Value'Class;
         Expected  : Natural;
         Done      : out Boolean;
         Observers : out Listener_Vectors.Vector);
      --  Stores only when the key's revision is still Expected.
      procedure Listen (Key : String; Observer : Listener_Access);
      procedure Unlisten (Key : String; Observer : Listener_Access);
      procedure Unlisten_All (Observer : Listener_Access);
      function Keys return Key_Vectors.Vector;
      function Stores return Long_Long_Integer;
   private
      Map   : Entry_Maps.Map;
      Count : Long_Long_Integer := 0;
   end Store;

   type Database is tagged limited record
      Data : Store;
   end record;

end Sancta.Runtime.Local_Databases;
