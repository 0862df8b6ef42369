with Ada.Unchecked_Deallocation;

package body RCL.Keyed_Caches is

   procedure Free is new Ada.Unchecked_Deallocation (Item, Item_Access);

   function Find_Or_Make
     (Key  : String;
      Init : not null access procedure (Made : in out Item)) return not null Item_Access
   is
      Result : Item_Access := Cache.Find (Key);
      Mine   : Item_Access;
      Kept   : Boolean;
   begin
      if Result = null then
         Mine := new Item;
         begin
            Init (Mine.all);
         exception
            when others =>
               Free (Mine);
               raise;
         end;
         Result := Mine;
         Cache.Insert (Key, Result, Kept);
         if not Kept then
            Free (Mine);
         end if;
      end if;
      return Result;
   end Find_Or_Make;

   protected body Cache is

      function Find (Key : String) return Item_Access is
        (if Items.Contains (Key) then Items.Element (Key) else null);

      procedure Insert (Key : String; Made : in out Item_Access; Kept : out Boolean) is
      begin
         Kept := not Items.Contains (Key);
         if Kept then
            Items.Insert (Key, Made);
         else
            Made := Items.Element (Key);
         end if;
      end Insert;

   end Cache;

end RCL.Keyed_Caches;
