--  The few functions of sqlite3.h that RCL.SQLite uses. Not for users.
with Interfaces.C;
with Interfaces.C.Strings;
with System;

private package RCL.SQLite.Thin is

   subtype C_Int is Interfaces.C.int;
   --  (RCL.SQLite.Int is a function.)

   SQLITE_OK       : constant := 0;
   SQLITE_ROW      : constant := 100;
   SQLITE_DONE     : constant := 101;
   SQLITE_OPEN_READONLY : constant := 16#0000_0001#;

   SQLITE_INTEGER  : constant := 1;
   SQLITE_FLOAT    : constant := 2;
   SQLITE_TEXT     : constant := 3;
   SQLITE_BLOB     : constant := 4;
   SQLITE_NULL     : constant := 5;

   function Open_V2
     (Filename : Interfaces.C.Strings.chars_ptr; Db : access System.Address; Flags : C_Int;
      Vfs : Interfaces.C.Strings.chars_ptr) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_open_v2";

   function Close_V2 (Db : System.Address) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_close_v2";

   function Errmsg (Db : System.Address) return Interfaces.C.Strings.chars_ptr
     with Import, Convention => C, External_Name => "sqlite3_errmsg";

   function Errstr (Code : C_Int) return Interfaces.C.Strings.chars_ptr
     with Import, Convention => C, External_Name => "sqlite3_errstr";

   function Prepare_V2
     (Db : System.Address; Sql : Interfaces.C.Strings.chars_ptr; N_Byte : C_Int;
      Stmt : access System.Address; Tail : System.Address) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_prepare_v2";

   function Step (Stmt : System.Address) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_step";

   function Finalize (Stmt : System.Address) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_finalize";

   function Column_Type (Stmt : System.Address; Col : C_Int) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_column_type";

   function Column_Int64 (Stmt : System.Address; Col : C_Int) return Interfaces.Integer_64
     with Import, Convention => C, External_Name => "sqlite3_column_int64";

   function Column_Text (Stmt : System.Address; Col : C_Int) return System.Address
     with Import, Convention => C, External_Name => "sqlite3_column_text";

   function Column_Blob (Stmt : System.Address; Col : C_Int) return System.Address
     with Import, Convention => C, External_Name => "sqlite3_column_blob";

   function Column_Bytes (Stmt : System.Address; Col : C_Int) return C_Int
     with Import, Convention => C, External_Name => "sqlite3_column_bytes";

end RCL.SQLite.Thin;
