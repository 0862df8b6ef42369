--  A task-safe map from a key to an object made on first use and kept for
--  the life of the process (the per-node clients of RCL.Clients and of
--  RCL.Services.Typed). The object is made outside the protected object
--  (making a client announces endpoints, which may block): Find, else make
--  one and Insert it; when another task inserted first, Insert returns that
--  task's object and the caller frees its own.
with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Strings.Hash;

private generic
   type Item_Access is private;
   No_Item : Item_Access;
package RCL.Keyed_Caches is

   package Item_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Item_Access, Ada.Strings.Hash, "=");

   protected Cache is
      function Find (Key : String) return Item_Access;
      --  No_Item when Key was never inserted.

      procedure Insert (Key : String; Made : in out Item_Access; Kept : out Boolean);
      --  Made becomes the cached object (another task's if it came first;
      --  Kept is then False).
   private
      Items : Item_Maps.Map;
   end Cache;

end RCL.Keyed_Caches;
