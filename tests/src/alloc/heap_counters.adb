with Ada.Task_Identification;

package body Heap_Counters is

   use Ada.Task_Identification;

   function Real_Malloc (Size : Interfaces.C.size_t) return System.Address
     with Import, Convention => C, External_Name => "__real___gnat_malloc";

   Watched_Task : System.Address := System.Null_Address with Volatile;
   Own   : Natural := 0 with Atomic;
   Total : Natural := 0 with Atomic;
   On    : Boolean := False with Atomic;

   function Identity return System.Address is
      Id : constant Task_Id := Current_Task;
      Raw : System.Address with Import, Address => Id'Address;
   begin
      return Raw;
   end Identity;

   procedure Start (Watched : System.Address) is
   begin
      Watched_Task := Watched;
      Own := 0;
      Total := 0;
      On := True;
   end Start;

   function Task_Allocations return Natural is (Own);
   function All_Allocations return Natural is (Total);

   function Counting_Malloc (Size : Interfaces.C.size_t) return System.Address is
      use type System.Address;
   begin
      if On then
         Total := Total + 1;
         if Identity = Watched_Task then
            Own := Own + 1;
         end if;
      end if;
      return Real_Malloc (Size);
   end Counting_Malloc;


end Heap_Counters;
