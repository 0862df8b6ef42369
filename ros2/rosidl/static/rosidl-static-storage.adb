with Ada.Task_Attributes;
with System.Address_To_Access_Conversions;
with System.Pool_Global;

package body ROSIDL.Static.Storage is

   use System.Storage_Elements;
   use type System.Address;

   package Selected is new Ada.Task_Attributes (Pool_Access, null);

   procedure Set_Task_Pool (Pool : Pool_Access) is
   begin
      Selected.Set_Value (Pool);
   end Set_Task_Pool;

   function Task_Pool return Pool_Access is (Selected.Value);

   Heap : constant Pool_Access := System.Pool_Global.Global_Pool_Object'Access;

   --  Each block starts with a header whose last word names the pool that
   --  made it; the header keeps the requested alignment.
   Word : constant Storage_Count := System.Address'Size / System.Storage_Unit;

   function Header_Size (Alignment : Storage_Count) return Storage_Count is
     (Storage_Count'Max (2 * Word, Alignment));

   package Pool_Cells is new System.Address_To_Access_Conversions (Pool_Access);

   overriding procedure Allocate
     (Pool      : in out Forwarding_Pool;
      Address   : out System.Address;
      Size      : Storage_Count;
      Alignment : Storage_Count)
   is
      pragma Unreferenced (Pool);
      Target : constant Pool_Access := (if Task_Pool = null then Heap else Task_Pool);
      Header : constant Storage_Count := Header_Size (Alignment);
      Raw    : System.Address;
   begin
      Target.Allocate (Raw, Size + Header, Storage_Count'Max (Alignment, Word));
      Address := Raw + Header;
      Pool_Cells.To_Pointer (Address - Word).all := Target;
   end Allocate;

   overriding procedure Deallocate
     (Pool      : in out Forwarding_Pool;
      Address   : System.Address;
      Size      : Storage_Count;
      Alignment : Storage_Count)
   is
      pragma Unreferenced (Pool);
      Header : constant Storage_Count := Header_Size (Alignment);
      Owner  : constant Pool_Access := Pool_Cells.To_Pointer (Address - Word).all;
   begin
      Owner.Deallocate (Address - Header, Size + Header, Storage_Count'Max (Alignment, Word));
   end Deallocate;

   overriding function Storage_Size (Pool : Forwarding_Pool) return Storage_Count is
     (Storage_Count'Last);

end ROSIDL.Static.Storage;
