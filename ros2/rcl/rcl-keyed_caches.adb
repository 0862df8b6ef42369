package body RCL.Keyed_Caches is

   protected body Cache is

      function Find (Key : String) return Item_Access is
        (if Items.Contains (Key) then Items.Element (Key) else No_Item);

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
