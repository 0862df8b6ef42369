with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with AUnit.Assertions;
with Sancta.Logging;
with Suite_Support; use Suite_Support;

package body Sancta.Runtime.Local_Databases.Tests is

   use AUnit.Assertions;
   use Ada.Strings.Unbounded;
   use Sancta.Runtime.Values;

   procedure Basics (Unused : in out Fixture) is
      DB : Database;
   begin
      Assert (not DB.Contains ("x"), "empty");
      DB.Put ("x", Integer_Value'(Data => 3));
      Assert (DB.Contains ("x"), "contains");
      Assert (Integer_Value (DB.Get ("x")).Data = 3, "get");
      Assert (DB.Revision ("x") = 1, "revision 1");
      DB.Put ("x", Real_Value'(Data => 1.5));
      Assert (DB.Get ("x") in Real_Value, "a key may change type");
      Assert (DB.Revision ("x") = 2, "revision 2");
      begin
         declare
            Unused_Value : constant Value'Class := DB.Get ("y");
         begin
            Assert (False, "Get of an absent key must raise");
         end;
      exception
         when E : Unknown_Key =>
            Assert (Ada.Exceptions.Exception_Message (E) = "no value under key 'y'",
                    Ada.Exceptions.Exception_Message (E));
      end;
      Assert (Natural (DB.Keys.Length) = 1, "one key");
   end Basics;

   --  A listener counting its notifications (called concurrently).
   protected type Counter is
      procedure Add;
      function Get return Natural;
   private
      N : Natural := 0;
   end Counter;

   protected body Counter is
      procedure Add is
      begin
         N := N + 1;
      end Add;
      function Get return Natural is (N);
   end Counter;

   type Counting_Listener is limited new Listener with record
      Count : Counter;
   end record;

   overriding procedure On_Key_Stored
     (This : in out Counting_Listener; Key : String; Item : Value'Class);
   overriding function Listener_Name (This : Counting_Listener) return String is ("counter");

   overriding procedure On_Key_Stored
     (This : in out Counting_Listener; Key : String; Item : Value'Class)
   is
      pragma Unreferenced (Key, Item);
   begin
      This.Count.Add;
   end On_Key_Stored;

   procedure Increment (Item : in out Value'Class) is
   begin
      Integer_Value (Item).Data := Integer_Value (Item).Data + 1;
   end Increment;

   --  Several tasks update one counter and put their own keys many times:
   --  the counter must equal the number of updates and every store must be
   --  notified exactly once.
   procedure Concurrent_Writers (Unused : in out Fixture) is
      Writers : constant := 4;
      Rounds  : constant := 2_000;
      DB      : aliased Database;
      Watch   : aliased Counting_Listener;
      Own     : aliased Counting_Listener;

      task type Writer (Id : Natural);

      task body Writer is
         Key : constant String := "own" & Ada.Strings.Fixed.Trim (Id'Image, Ada.Strings.Left);
      begin
         for I in 1 .. Rounds loop
            DB.Update ("counter", Increment'Access);
            DB.Put (Key, Integer_Value'(Data => Long_Long_Integer (I)));
         end loop;
      end Writer;

   begin
      DB.Put ("counter", Integer_Value'(Data => 0));
      DB.Listen ("counter", Watch'Unchecked_Access);
      for W in 1 .. Writers loop
         DB.Listen ("own" & Ada.Strings.Fixed.Trim (W'Image, Ada.Strings.Left),
                    Own'Unchecked_Access);
      end loop;
      declare
         type Writer_Access is access Writer;
         --  Declared in this block: the block waits for the tasks.
         Team : array (1 .. Writers) of Writer_Access;
      begin
         for W in Team'Range loop
            Team (W) := new Writer (W);
         end loop;
      end;
      Assert (Integer_Value (DB.Get ("counter")).Data = Writers * Rounds,
              "lost updates: counter =" & Integer_Value (DB.Get ("counter")).Data'Image);
      Assert (Watch.Count.Get = Writers * Rounds,
              "counter notifications:" & Watch.Count.Get'Image);
      Assert (Own.Count.Get = Writers * Rounds, "own-key notifications:" & Own.Count.Get'Image);
      for W in 1 .. Writers loop
         Assert (Integer_Value
                   (DB.Get ("own" & Ada.Strings.Fixed.Trim (W'Image, Ada.Strings.Left))).Data
                 = Rounds, "last value of each writer");
      end loop;
      Assert (DB.Revision ("counter") = Writers * Rounds + 1, "revisions");
   end Concurrent_Writers;

   --  A listener that copies what it hears to another key.
   type Forwarding_Listener (Target : access Database) is limited new Listener with record
      To : Unbounded_String;
   end record;

   overriding procedure On_Key_Stored
     (This : in out Forwarding_Listener; Key : String; Item : Value'Class);
   overriding function Listener_Name (This : Forwarding_Listener) return String is
     ("forward to " & To_String (This.To));

   overriding procedure On_Key_Stored
     (This : in out Forwarding_Listener; Key : String; Item : Value'Class)
   is
      pragma Unreferenced (Key);
   begin
      This.Target.Put (To_String (This.To), Item);
   end On_Key_Stored;

   procedure Recursion (Unused : in out Fixture) is
      DB       : aliased Database;
      A_To_B   : aliased Forwarding_Listener (DB'Access);
      B_To_C   : aliased Forwarding_Listener (DB'Access);
      C_To_A   : aliased Forwarding_Listener (DB'Access);
      Raised   : Boolean := False;
   begin
      A_To_B.To := To_Unbounded_String ("b");
      B_To_C.To := To_Unbounded_String ("c");
      C_To_A.To := To_Unbounded_String ("a");
      DB.Listen ("a", A_To_B'Unchecked_Access);
      DB.Listen ("b", B_To_C'Unchecked_Access);
      --  A chain without a cycle works.
      DB.Put ("a", Integer_Value'(Data => 1));
      Assert (Integer_Value (DB.Get ("c")).Data = 1, "chain a -> b -> c");
      DB.Listen ("c", C_To_A'Unchecked_Access);
      for Attempt in 1 .. 2 loop
         Raised := False;
         begin
            DB.Put ("a", Integer_Value'(Data => 2));
         exception
            when E : Listener_Recursion =>
               Raised := True;
               Assert (Ada.Exceptions.Exception_Message (E)
                       = "listener recursion: a -> b -> c -> a",
                       "message: " & Ada.Exceptions.Exception_Message (E));
         end;
         Assert (Raised, "a cycle must raise Listener_Recursion (attempt" & Attempt'Image & ")");
      end loop;
      --  The task's chain was cleared: an unrelated store still works.
      DB.Put ("d", Integer_Value'(Data => 5));
      Assert (DB.Contains ("d"), "database usable after a recursion");
      DB.Unlisten ("c", C_To_A'Unchecked_Access);
      DB.Put ("a", Integer_Value'(Data => 3));
      Assert (Integer_Value (DB.Get ("c")).Data = 3, "cycle broken by Unlisten");
   end Recursion;

   type Failing_Listener is limited new Listener with null record;
   overriding procedure On_Key_Stored
     (This : in out Failing_Listener; Key : String; Item : Value'Class);
   overriding function Listener_Name (This : Failing_Listener) return String is ("failing");

   overriding procedure On_Key_Stored
     (This : in out Failing_Listener; Key : String; Item : Value'Class) is
   begin
      raise Constraint_Error with "broken listener";
   end On_Key_Stored;

   procedure Failing_Listeners (Unused : in out Fixture) is
      DB     : Database;
      Bad    : aliased Failing_Listener;
      Good   : aliased Counting_Listener;
      Before : constant Natural := Logging.Printed (Logging.Error);
   begin
      Logging.Set_Console (False);
      DB.Listen ("k", Bad'Unchecked_Access);
      DB.Listen ("k", Good'Unchecked_Access);
      DB.Listen ("k", Good'Unchecked_Access);
      DB.Put ("k", Boolean_Value'(Data => True));
      Logging.Set_Console (True);
      Assert (Good.Count.Get = 1, "the other listener ran once (no duplicates)");
      Assert (Logging.Printed (Logging.Error) = Before + 1, "the failure was logged");
      Assert (Contains (Logging.Last_Message, "listener failing of key 'k'"),
              Logging.Last_Message);
   end Failing_Listeners;

   procedure Wrong_Tag (Item : in out Value'Class) is
   begin
      Item := Value'Class (Real_Value'(Data => 1.0));
   end Wrong_Tag;

   procedure Update_Rules (Unused : in out Fixture) is
      DB : Database;
   begin
      begin
         DB.Update ("none", Increment'Access);
         Assert (False, "Update of an absent key must raise");
      exception
         when Unknown_Key =>
            null;
      end;
      DB.Put ("n", Integer_Value'(Data => 1));
      begin
         DB.Update ("n", Wrong_Tag'Access);
         Assert (False, "changing the tag must raise");
      exception
         when Constraint_Error =>
            null;
      end;
      Assert (Integer_Value (DB.Get ("n")).Data = 1, "value kept");
   end Update_Rules;

   function Suite return AUnit.Test_Suites.Access_Test_Suite is
      Result : constant AUnit.Test_Suites.Access_Test_Suite := new AUnit.Test_Suites.Test_Suite;
   begin
      Result.Add_Test (Caller.Create ("database: put, get, revisions", Basics'Access));
      Result.Add_Test (Caller.Create ("database: concurrent writers, nothing lost",
                                      Concurrent_Writers'Access));
      Result.Add_Test (Caller.Create ("database: listener recursion detected", Recursion'Access));
      Result.Add_Test (Caller.Create ("database: failing listener logged, others run",
                                      Failing_Listeners'Access));
      Result.Add_Test (Caller.Create ("database: update rules", Update_Rules'Access));
      return Result;
   end Suite;

end Sancta.Runtime.Local_Databases.Tests;
