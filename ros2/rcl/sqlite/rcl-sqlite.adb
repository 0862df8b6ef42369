with Interfaces.C.Strings;
with RCL.SQLite.Thin;

package body RCL.SQLite is

   use Ada.Strings.Unbounded;
   use type Interfaces.C.int;
   use type System.Address;

   function Message (DB : System.Address; Code : Interfaces.C.int) return String is
      use Interfaces.C.Strings;
      Text : constant chars_ptr :=
        (if DB /= System.Null_Address then Thin.Errmsg (DB) else Thin.Errstr (Code));
   begin
      return (if Text = Null_Ptr then "SQLite error" & Code'Image else Value (Text));
   end Message;

   procedure Fail (Path : Unbounded_String; DB : System.Address; Code : Interfaces.C.int) is
   begin
      raise SQLite_Error with To_String (Path) & ": " & Message (DB, Code);
   end Fail;

   --------------
   -- Database --
   --------------

   procedure Open_Read_Only (This : in out Database; Path : String; Label : String := "") is
      use Interfaces.C.Strings;
      Name   : chars_ptr := New_String (Path);
      Handle : aliased System.Address := System.Null_Address;
      Code   : constant Interfaces.C.int :=
        Thin.Open_V2 (Name, Handle'Access, Thin.SQLITE_OPEN_READONLY, Null_Ptr);
   begin
      Free (Name);
      This.Path := To_Unbounded_String (if Label = "" then Path else Label);
      if Code /= Thin.SQLITE_OK then
         declare
            Text : constant String := Message (Handle, Code);
         begin
            if Handle /= System.Null_Address then
               Code_Ignored : declare
                  Ignored : constant Interfaces.C.int := Thin.Close_V2 (Handle);
               begin
                  null;
               end Code_Ignored;
            end if;
            raise SQLite_Error with To_String (This.Path) & ": " & Text;
         end;
      end if;
      This.Handle := Handle;
   end Open_Read_Only;

   function Is_Open (This : Database) return Boolean is (This.Handle /= System.Null_Address);

   function Path (This : Database) return String is (To_String (This.Path));

   procedure Close (This : in out Database) is
   begin
      if This.Handle /= System.Null_Address then
         declare
            Ignored : constant Interfaces.C.int := Thin.Close_V2 (This.Handle);
            --  close_v2 defers the closing while statements are unfinished.
         begin
            This.Handle := System.Null_Address;
         end;
      end if;
   end Close;

   overriding procedure Finalize (This : in out Database) is
   begin
      Close (This);
   exception
      when others => null;
   end Finalize;

   function Table_Exists (This : Database; Table : String) return Boolean is
      S : Statement;
   begin
      S.Prepare (This, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = '"
                 & Table & "'");
      return S.Step;
   end Table_Exists;

   function Has_Column (This : Database; Table, Column : String) return Boolean is
      S : Statement;
   begin
      S.Prepare (This, "SELECT 1 FROM pragma_table_info('" & Table & "') WHERE name = '"
                 & Column & "'");
      return S.Step;
   end Has_Column;

   ---------------
   -- Statement --
   ---------------

   procedure Prepare (This : in out Statement; DB : Database'Class; SQL : String) is
      use Interfaces.C.Strings;
      Text   : chars_ptr := New_String (SQL);
      Handle : aliased System.Address := System.Null_Address;
      Code   : constant Interfaces.C.int :=
        Thin.Prepare_V2 (DB.Handle, Text, -1, Handle'Access, System.Null_Address);
   begin
      Free (Text);
      Finish (This);
      This.DB := DB.Handle;
      This.Path := DB.Path;
      if Code /= Thin.SQLITE_OK then
         Fail (This.Path, DB.Handle, Code);
      end if;
      This.Handle := Handle;
   end Prepare;

   function Step (This : in out Statement) return Boolean is
      Code : constant Interfaces.C.int := Thin.Step (This.Handle);
   begin
      if Code = Thin.SQLITE_ROW then
         return True;
      elsif Code = Thin.SQLITE_DONE then
         return False;
      end if;
      Fail (This.Path, This.DB, Code);
      return False;
   end Step;

   function Kind (This : Statement; Column : Natural) return Value_Kind is
     (case Thin.Column_Type (This.Handle, Interfaces.C.int (Column)) is
         when Thin.SQLITE_INTEGER => Integer_Value,
         when Thin.SQLITE_FLOAT   => Float_Value,
         when Thin.SQLITE_TEXT    => Text_Value,
         when Thin.SQLITE_BLOB    => Blob_Value,
         when others              => Null_Value);

   function Kind_Name (Kind : Value_Kind) return String is
     (case Kind is
         when Integer_Value => "integer", when Float_Value => "real",
         when Text_Value => "text", when Blob_Value => "blob", when Null_Value => "null");

   function Int (This : Statement; Column : Natural) return Interfaces.Integer_64 is
     (Thin.Column_Int64 (This.Handle, Interfaces.C.int (Column)));

   function Text (This : Statement; Column : Natural) return String is
      Start  : constant System.Address :=
        Thin.Column_Text (This.Handle, Interfaces.C.int (Column));
      Length : constant Natural :=
        Natural (Thin.Column_Bytes (This.Handle, Interfaces.C.int (Column)));
   begin
      if Start = System.Null_Address or else Length = 0 then
         return "";
      end if;
      declare
         Result : constant String (1 .. Length)
           with Import, Address => Start;
      begin
         return Result;
      end;
   end Text;

   procedure Blob
     (This    : Statement;
      Column  : Natural;
      Process : not null access procedure (Data : Ada.Streams.Stream_Element_Array))
   is
      use Ada.Streams;
      Start  : constant System.Address :=
        Thin.Column_Blob (This.Handle, Interfaces.C.int (Column));
      Length : constant Stream_Element_Offset :=
        Stream_Element_Offset (Thin.Column_Bytes (This.Handle, Interfaces.C.int (Column)));
      Empty  : constant Stream_Element_Array (1 .. 0) := [others => 0];
   begin
      if Start = System.Null_Address or else Length = 0 then
         Process (Empty);
         return;
      end if;
      declare
         Data : constant Stream_Element_Array (1 .. Length)
           with Import, Address => Start;
      begin
         Process (Data);
      end;
   end Blob;

   procedure Finish (This : in out Statement) is
   begin
      if This.Handle /= System.Null_Address then
         declare
            Ignored : constant Interfaces.C.int := Thin.Finalize (This.Handle);
         begin
            This.Handle := System.Null_Address;
         end;
      end if;
   end Finish;

   overriding procedure Finalize (This : in out Statement) is
   begin
      Finish (This);
   exception
      when others => null;
   end Finalize;

end RCL.SQLite;
