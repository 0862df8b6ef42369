--  A task-safe map from a key to an object made on first use and kept for
--  the life of the process (the per-node clients of RCL.Clients and of
--  RCL.Services.Typed). The object is made outside the protected object
--  (making a client announces endpoints, which may block); when another
--  task inserted the same key first, that task's object is kept and the
--  one just made is freed.
with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Strings.Hash;

private generic
   type Item is limited private;
   type Item_Access is access Item;
package RCL.Keyed_Caches is

   function Find_Or_Make
     (Key  : String;
      Init : not null access procedure (Made : in out Item)) return not null Item_Access;
   --  The object cached under Key; the first call for a Key allocates one and
   --  calls Init on it (if Init raises, the object is freed, nothing is
   --  cached and the exception propagates).

private

   package Item_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Item_Access, Ada.Strings.Hash, "=");

   protected Cache is
      function Find (Key : String) return Item_Access;
      --  null when Key was never inserted.

      procedure Insert (Key : String; Made : in out Item_Access; Kept : out Boolean);
      --  Made becomes the cached object (another task's if it came first;
      --  Kept is then False).
   private
      Items : Item_Maps.Map;
   end Cache;

end RCL.Keyed_Caches;
