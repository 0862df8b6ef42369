--  Reading SQLite 3 databases (Debian's libsqlite3) for rosbag2's sqlite3
--  storage: a database is opened read-only (SQLITE_OPEN_READONLY: the
--  user's file is never written), statements are prepared from fixed SQL
--  and stepped row by row. Every failure raises SQLite_Error whose message
--  is the file and SQLite's own text ("run_0.db3: file is not a
--  database"). No C type is visible here: RCL.SQLite.Thin holds them.
--  Example:
--     DB : Database;
--     DB.Open_Read_Only ("run/run_0.db3");
--     declare
--        S : Statement;
--     begin
--        S.Prepare (DB, "SELECT id, name FROM topics ORDER BY id");
--        while S.Step loop
--           Put_Line (S.Int (0)'Image & " " & S.Text (1));
--        end loop;
--     end;
with Ada.Finalization;
with Ada.Streams;
with Interfaces;
with System;

private with Ada.Strings.Unbounded;

package RCL.SQLite is

   SQLite_Error : exception;

   type Database is new Ada.Finalization.Limited_Controlled with private;

   procedure Open_Read_Only (This : in out Database; Path : String; Label : String := "")
     with Pre => not This.Is_Open;
   --  SQLite_Error when the file cannot be opened. A file that is no
   --  database is found out by the first statement. Errors name the file
   --  Label (Path when "").

   function Is_Open (This : Database) return Boolean;

   function Path (This : Database) return String;

   procedure Close (This : in out Database);
   overriding procedure Finalize (This : in out Database);

   function Table_Exists (This : Database; Table : String) return Boolean
     with Pre => This.Is_Open;
   function Has_Column (This : Database; Table, Column : String) return Boolean
     with Pre => This.Is_Open;
   --  Table and Column are names the caller wrote (letters, digits, _).

   type Statement is new Ada.Finalization.Limited_Controlled with private;

   procedure Prepare (This : in out Statement; DB : Database'Class; SQL : String)
     with Pre => DB.Is_Open;
   --  The statement stays valid while DB stays open.

   function Step (This : in out Statement) return Boolean;
   --  True when a row is there to read, False when there is no more.

   type Value_Kind is (Integer_Value, Float_Value, Text_Value, Blob_Value, Null_Value);

   function Kind (This : Statement; Column : Natural) return Value_Kind;
   --  Of the current row's column (0 is the first).
   function Kind_Name (Kind : Value_Kind) return String;
   --  "integer", "real", "text", "blob", "null", as SQLite's typeof.

   function Int (This : Statement; Column : Natural) return Interfaces.Integer_64;
   function Text (This : Statement; Column : Natural) return String;
   --  As SQLite converts the value when it has another kind.

   procedure Blob
     (This    : Statement;
      Column  : Natural;
      Process : not null access procedure (Data : Ada.Streams.Stream_Element_Array));
   --  The column's bytes, valid during Process only (not copied).

   procedure Finish (This : in out Statement);
   overriding procedure Finalize (This : in out Statement);

private

   type Database is new Ada.Finalization.Limited_Controlled with record
      Handle : System.Address := System.Null_Address;
      Path   : Ada.Strings.Unbounded.Unbounded_String;
   end record;

   type Statement is new Ada.Finalization.Limited_Controlled with record
      Handle : System.Address := System.Null_Address;
      DB     : System.Address := System.Null_Address;
      Path   : Ada.Strings.Unbounded.Unbounded_String;
   end record;

end RCL.SQLite;
