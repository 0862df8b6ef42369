with Ada.Command_Line;
with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Exceptions;
with Ada.Finalization;
with Ada.IO_Exceptions;
with Ada.Streams.Stream_IO;
with Ada.Strings.Fixed;
with Ada.Strings.Hash;
with Ada.Strings.Unbounded;
with GNAT.OS_Lib;
with ROSIDL.Parser;
with ROSIDL.Mutexes;

package body ROSIDL.Interfaces is

   use Ada.Strings.Unbounded;
   use type Ada.Directories.File_Kind;

   package Message_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Message_Access, Ada.Strings.Hash, "=");
   package Service_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Service_Access, Ada.Strings.Hash, "=");
   package Action_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, Action_Access, Ada.Strings.Hash, "=");
   package Name_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);

   type Message_Access_Array is array (Positive range <>) of Message_Access;

   ---------------------------------------------------------------------------
   --  Shared state: the cache (definitions are never freed) and the folders
   --  added through Add_Folder.

   protected Registry is
      function Find_Message (Key : String) return Message_Access;
      function Find_Service (Key : String) return Service_Access;
      function Find_Action (Key : String) return Action_Access;
      --  null when not cached.
      procedure Insert_Message (Key : String; Value : Message_Access);
      procedure Insert_Service (Key : String; Value : Service_Access);
      procedure Insert_Action (Key : String; Value : Action_Access);
      procedure Append_Folder (Folder : String);
      procedure Delete_Folder (Folder : String);
      function Added_Folders return String_Vectors.Vector;
   private
      Message_Cache : Message_Maps.Map;
      Service_Cache : Service_Maps.Map;
      Action_Cache  : Action_Maps.Map;
      Folders       : String_Vectors.Vector;
   end Registry;

   protected body Registry is

      function Find_Message (Key : String) return Message_Access is
        (if Message_Cache.Contains (Key) then Message_Cache.Element (Key) else null);

      function Find_Service (Key : String) return Service_Access is
        (if Service_Cache.Contains (Key) then Service_Cache.Element (Key) else null);

      function Find_Action (Key : String) return Action_Access is
        (if Action_Cache.Contains (Key) then Action_Cache.Element (Key) else null);

      procedure Insert_Message (Key : String; Value : Message_Access) is
      begin
         Message_Cache.Include (Key, Value);
      end Insert_Message;

      procedure Insert_Service (Key : String; Value : Service_Access) is
      begin
         Service_Cache.Include (Key, Value);
      end Insert_Service;

      procedure Insert_Action (Key : String; Value : Action_Access) is
      begin
         Action_Cache.Include (Key, Value);
      end Insert_Action;

      procedure Append_Folder (Folder : String) is
      begin
         if not Folders.Contains (Folder) then
            Folders.Append (Folder);
         end if;
      end Append_Folder;

      procedure Delete_Folder (Folder : String) is
         I : constant Natural := Folders.Find_Index (Folder);
      begin
         if I /= String_Vectors.No_Index then
            Folders.Delete (I);
         end if;
      end Delete_Folder;

      function Added_Folders return String_Vectors.Vector is (Folders);

   end Registry;

   ---------------------------------------------------------------------------
   --  Loading is serialised: one task parses at a time (a nested type is
   --  loaded while its parent is parsed), look-ups of cached definitions
   --  only take the Registry's read lock.

   Load_Lock : ROSIDL.Mutexes.Mutex;

   type Lock_Holder is new Ada.Finalization.Limited_Controlled with record
      Held : Boolean := False;
   end record;
   --  Holds Load_Lock for its lifetime.

   overriding procedure Initialize (This : in out Lock_Holder);
   overriding procedure Finalize (This : in out Lock_Holder);

   overriding procedure Initialize (This : in out Lock_Holder) is
   begin
      Load_Lock.Seize;
      This.Held := True;
   end Initialize;

   overriding procedure Finalize (This : in out Lock_Holder) is
   begin
      if This.Held then
         This.Held := False;
         Load_Lock.Release;
      end if;
   end Finalize;

   In_Progress : String_Vectors.Vector;
   --  The messages being parsed, outermost first (only used under Load_Lock):
   --  meeting one of them again is a recursive definition.

   ---------------------------------------------------------------------------
   --  The search path

   function Is_Folder (Path : String) return Boolean is
     (Path'Length > 0
      and then Ada.Directories.Exists (Path)
      and then Ada.Directories.Kind (Path) = Ada.Directories.Directory);

   function Is_File (Path : String) return Boolean is
     (Ada.Directories.Exists (Path)
      and then Ada.Directories.Kind (Path) = Ada.Directories.Ordinary_File);

   function Executable_Folder return String is
      --  The folder of the running program, "" when it cannot be found.
      use GNAT.OS_Lib;
   begin
      if Is_File ("/proc/self/exe") then
         return Ada.Directories.Containing_Directory
           (Normalize_Pathname ("/proc/self/exe", Resolve_Links => True));
      end if;
      declare
         Command : constant String := Ada.Command_Line.Command_Name;
         Found   : GNAT.OS_Lib.String_Access :=
           (if Ada.Strings.Fixed.Index (Command, "/") > 0 then new String'(Command)
            else Locate_Exec_On_Path (Command));
      begin
         if Found = null then
            return "";
         end if;
         declare
            Full : constant String := Normalize_Pathname (Found.all, Resolve_Links => True);
         begin
            Free (Found);
            return Ada.Directories.Containing_Directory (Full);
         end;
      end;
   exception
      when Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error =>
         return "";
   end Executable_Folder;

   function Bundled_Folder (Name : String := "ros2_interfaces") return String is
   begin
      if Ada.Environment_Variables.Exists (Root_Variable)
        and then Ada.Environment_Variables.Value (Root_Variable) /= ""
      then
         return Ada.Environment_Variables.Value (Root_Variable) & "/share/" & Name;
      end if;
      declare
         Exe : constant String := Executable_Folder;
      begin
         return (if Exe = "" then "" else Exe & "/../share/" & Name);
      end;
   end Bundled_Folder;

   procedure Add_Folder (Folder : String) is
   begin
      if not Is_Folder (Folder) then
         raise Definition_Error with
           Folder & ": expected an interface folder, found no such directory";
      end if;
      Registry.Append_Folder (Ada.Directories.Full_Name (Folder));
   end Add_Folder;

   procedure Remove_Folder (Folder : String) is
   begin
      Registry.Delete_Folder
        (if Is_Folder (Folder) then Ada.Directories.Full_Name (Folder) else Folder);
   end Remove_Folder;

   function Search_Path return String_Vectors.Vector is
      Result : String_Vectors.Vector;

      procedure Add (Folder : String) is
      begin
         if Is_Folder (Folder) then
            declare
               Full : constant String := Ada.Directories.Full_Name (Folder);
            begin
               if not Result.Contains (Full) then
                  Result.Append (Full);
               end if;
            end;
         end if;
      end Add;

      procedure Add_Each (Variable : String; Suffix : String := "") is
         --  Each folder of a colon-separated list in Variable, + Suffix.
      begin
         if not Ada.Environment_Variables.Exists (Variable) then
            return;
         end if;
         declare
            Value : constant String := Ada.Environment_Variables.Value (Variable);
            First : Positive := Value'First;
         begin
            for I in Value'Range loop
               if Value (I) = ':' then
                  if I > First then
                     Add (Value (First .. I - 1) & Suffix);
                  end if;
                  First := I + 1;
               end if;
            end loop;
            if First <= Value'Last then
               Add (Value (First .. Value'Last) & Suffix);
            end if;
         end;
      end Add_Each;

   begin
      Add (Bundled_Folder);
      Add_Each (Ament_Variable, Suffix => "/share");
      Add_Each (Path_Variable);
      for F of Registry.Added_Folders loop
         Add (F);
      end loop;
      return Result;
   end Search_Path;

   function Path_Image return String is
      Result : Unbounded_String;
   begin
      for F of Search_Path loop
         Append (Result, (if Length (Result) = 0 then "" else ":") & F);
      end loop;
      return (if Length (Result) = 0 then "(empty)" else To_String (Result));
   end Path_Image;

   function Package_Folder (Package_Name : String) return String is
      --  The folder of the package on the path (the first one wins), "" when
      --  there is none.
   begin
      if not ROSIDL.Parser.Is_Valid_Package_Name (Package_Name) then
         return "";
      end if;
      for F of Search_Path loop
         if Is_Folder (F & "/" & Package_Name) then
            return F & "/" & Package_Name;
         end if;
      end loop;
      return "";
   end Package_Folder;

   function Interface_File (Package_Name, Kind, Name : String) return String is
      --  The file <package>/<kind>/<Name>.<kind>, "" when there is none.
      Folder : constant String := Package_Folder (Package_Name);
   begin
      if Folder = "" or else not ROSIDL.Parser.Is_Valid_Type_Name (Name) then
         return "";
      end if;
      declare
         Path : constant String := Folder & "/" & Kind & "/" & Name & "." & Kind;
      begin
         return (if Is_File (Path) then Path else "");
      end;
   end Interface_File;

   function Read_File (Path : String) return String is
      use Ada.Streams.Stream_IO;
      File : File_Type;
   begin
      Open (File, In_File, Path);
      declare
         Text : String (1 .. Natural (Size (File)));
      begin
         String'Read (Stream (File), Text);
         Close (File);
         return Text;
      end;
   exception
      when Ada.IO_Exceptions.Name_Error | Ada.IO_Exceptions.Use_Error
         | Ada.IO_Exceptions.Device_Error | Ada.IO_Exceptions.End_Error =>
         if Is_Open (File) then
            Close (File);
         end if;
         raise Definition_Error with Path & ":0:0: expected a readable file, found an I/O error";
   end Read_File;

   function Not_Found (Package_Name, Kind, Name : String) return String is
     ("unknown " & Kind & " type " & Package_Name & "/" & Kind & "/" & Name
      & (if Package_Folder (Package_Name) = ""
         then ": no package " & Package_Name
         else ": no file " & Kind & "/" & Name & "." & Kind & " in package " & Package_Name)
      & " on the interface search path " & Path_Image);

   ---------------------------------------------------------------------------
   --  Loading (under Load_Lock)

   function Load_Message
     (Package_Name, Name : String; Where : Source_Position) return Message_Access;

   function Short (Key : String) return String is
      --  "pkg/msg/Name" as "pkg/Name".
      At_Kind : constant Natural := Ada.Strings.Fixed.Index (Key, "/msg/");
   begin
      return (if At_Kind = 0 then Key
              else Key (Key'First .. At_Kind) & Key (At_Kind + 5 .. Key'Last));
   end Short;

   function Type_Part (Key : String) return String is
     (Key (Ada.Strings.Fixed.Index (Key, "/", Ada.Strings.Backward) + 1 .. Key'Last));
   --  "pkg/msg/Name" as "Name".

   function Image (N : Natural) return String is
     (Ada.Strings.Fixed.Trim (N'Image, Ada.Strings.Left));

   function Locked_Resolver
     (Package_Name, Name : String; Where : Source_Position) return Message_Access is
     (Load_Message (Package_Name, Name, Where));

   function Load_Message
     (Package_Name, Name : String; Where : Source_Position) return Message_Access
   is
      Key    : constant String := Package_Name & "/msg/" & Name;
      Cached : constant Message_Access := Registry.Find_Message (Key);
   begin
      if Cached /= null then
         return Cached;
      end if;
      if In_Progress.Contains (Key) then
         declare
            Chain : Unbounded_String;
         begin
            for I in In_Progress.Find_Index (Key) .. In_Progress.Last_Index loop
               Append (Chain, Type_Part (In_Progress (I)) & " -> ");
            end loop;
            raise Definition_Error with
              Image (Where) & ": expected a type that does not nest itself, found '"
              & Short (Key) & "' (" & To_String (Chain) & Type_Part (Key) & ")";
         end;
      end if;
      declare
         Path : constant String := Interface_File (Package_Name, "msg", Name);
         Result : Message_Access;
      begin
         if Path = "" then
            return null;
         end if;
         In_Progress.Append (Key);
         begin
            Result := ROSIDL.Parser.Parse_Message
              (Package_Name, Name, Read_File (Path), Path, Locked_Resolver'Access);
         exception
            when E : Definition_Error =>
               In_Progress.Delete_Last;
               if Where.Line = 0 then
                  raise;
               end if;
               --  Say where the broken definition was needed.
               raise Definition_Error with
                 Ada.Exceptions.Exception_Message (E) & " (needed by "
                 & Ada.Directories.Simple_Name (To_String (Where.File)) & ":"
                 & Image (Where.Line) & ":" & Image (Where.Column) & ")";
            when others =>
               In_Progress.Delete_Last;
               raise;
         end;
         In_Progress.Delete_Last;
         Registry.Insert_Message (Key, Result);
         return Result;
      end;
   end Load_Message;

   generic
      type Definition (<>) is limited private;
      type Definition_Access is access constant Definition;
      Folder : String;
      --  "srv" or "action".
      with function Find (Key : String) return Definition_Access;
      with function Parse
        (Package_Name, Name, Text : String;
         File    : String;
         Resolve : not null ROSIDL.Parser.Resolver) return Definition_Access;
      with procedure Register (Package_Name, Key : String; Parsed : Definition_Access);
      --  Caches Parsed under Key, and its messages.
   function Load_Parsed (Package_Name, Name : String) return Definition_Access;
   --  The cached definition, else the parsed file (null when there is none).

   function Load_Parsed (Package_Name, Name : String) return Definition_Access is
      Key    : constant String := Package_Name & "/" & Folder & "/" & Name;
      Cached : constant Definition_Access := Find (Key);
   begin
      if Cached /= null then
         return Cached;
      end if;
      declare
         Path   : constant String := Interface_File (Package_Name, Folder, Name);
         Result : Definition_Access;
      begin
         if Path = "" then
            return null;
         end if;
         Result := Parse (Package_Name, Name, Read_File (Path), Path, Locked_Resolver'Access);
         Register (Package_Name, Key, Result);
         return Result;
      end;
   end Load_Parsed;

   procedure Register_Service (Package_Name, Key : String; Parsed : Service_Access) is
      pragma Unreferenced (Package_Name);
   begin
      Registry.Insert_Message (Key & "_Request", Parsed.Request);
      Registry.Insert_Message (Key & "_Response", Parsed.Response);
      Registry.Insert_Service (Key, Parsed);
   end Register_Service;

   procedure Register_Action (Package_Name, Key : String; Parsed : Action_Access) is
   begin
      for M of Message_Access_Array'
        [Parsed.Goal, Parsed.Result, Parsed.Feedback, Parsed.Feedback_Message,
         Parsed.Send_Goal.Request, Parsed.Send_Goal.Response,
         Parsed.Get_Result.Request, Parsed.Get_Result.Response]
      loop
         Registry.Insert_Message (Package_Name & "/action/" & To_String (M.Name), M);
      end loop;
      Registry.Insert_Action (Key, Parsed);
   end Register_Action;

   function Load_Service is new Load_Parsed
     (Service_Definition, Service_Access, "srv", Registry.Find_Service,
      ROSIDL.Parser.Parse_Service, Register_Service);

   function Load_Action is new Load_Parsed
     (Action_Definition, Action_Access, "action", Registry.Find_Action,
      ROSIDL.Parser.Parse_Action, Register_Action);

   ---------------------------------------------------------------------------
   --  Look-ups

   No_Position : constant Source_Position := (Null_Unbounded_String, 0, 0);

   generic
      type Definition (<>) is limited private;
      type Definition_Access is access constant Definition;
      Folder : String;
      --  "msg", "srv" or "action".
      with function Find (Key : String) return Definition_Access;
      with function Load (Package_Name, Name : String) return Definition_Access;
   function Cached_Or_Loaded (Package_Name, Name : String) return Definition_Access;
   --  The cached definition, else loaded (under the loader lock), else
   --  Unknown_Type.

   function Cached_Or_Loaded (Package_Name, Name : String) return Definition_Access is
      Cached : constant Definition_Access :=
        Find (Package_Name & "/" & Folder & "/" & Name);
   begin
      if Cached /= null then
         return Cached;
      end if;
      declare
         Lock   : Lock_Holder;
         pragma Unreferenced (Lock);
         Result : constant Definition_Access := Load (Package_Name, Name);
      begin
         if Result = null then
            raise Unknown_Type with Not_Found (Package_Name, Folder, Name);
         end if;
         return Result;
      end;
   end Cached_Or_Loaded;

   function Load_Message_Anywhere (Package_Name, Name : String) return Message_Access is
     (Load_Message (Package_Name, Name, No_Position));

   function Message_Look_Up is new Cached_Or_Loaded
     (Message_Definition, Message_Access, "msg", Registry.Find_Message, Load_Message_Anywhere);
   function Service_Look_Up is new Cached_Or_Loaded
     (Service_Definition, Service_Access, "srv", Registry.Find_Service, Load_Service);
   function Action_Look_Up is new Cached_Or_Loaded
     (Action_Definition, Action_Access, "action", Registry.Find_Action, Load_Action);

   function Message (Package_Name, Name : String) return Message_Access
     renames Message_Look_Up;

   function Service (Package_Name, Name : String) return Service_Access
     renames Service_Look_Up;

   function Action (Package_Name, Name : String) return Action_Access
     renames Action_Look_Up;

   function Ends_With (S, Suffix : String) return Boolean is
     (S'Length > Suffix'Length
      and then S (S'Last - Suffix'Length + 1 .. S'Last) = Suffix);

   function Without (S, Suffix : String) return String is
     (S (S'First .. S'Last - Suffix'Length));

   function Message (Full_Name : String) return Message_Access is
      First_Slash : constant Natural := Ada.Strings.Fixed.Index (Full_Name, "/");
      Last_Slash  : constant Natural :=
        Ada.Strings.Fixed.Index (Full_Name, "/", Ada.Strings.Backward);
   begin
      if First_Slash = 0 then
         raise Unknown_Type with
           "unknown message type " & Full_Name & ": expected 'package/msg/Name' or"
           & " 'package/Name'";
      end if;
      declare
         Pkg  : constant String := Full_Name (Full_Name'First .. First_Slash - 1);
         Name : constant String := Full_Name (Last_Slash + 1 .. Full_Name'Last);
         Kind : constant String :=
           (if First_Slash = Last_Slash then "msg"
            else Full_Name (First_Slash + 1 .. Last_Slash - 1));
      begin
         if Kind = "msg" then
            return Message (Pkg, Name);
         elsif Kind = "srv" and then Ends_With (Name, "_Request") then
            return Service (Pkg, Without (Name, "_Request")).Request;
         elsif Kind = "srv" and then Ends_With (Name, "_Response") then
            return Service (Pkg, Without (Name, "_Response")).Response;
         elsif Kind = "action" then
            for Suffix of String_Vectors.Vector'
              ["_SendGoal_Request", "_SendGoal_Response", "_GetResult_Request",
               "_GetResult_Response", "_FeedbackMessage", "_Goal", "_Result", "_Feedback"]
            loop
               if Ends_With (Name, Suffix) then
                  declare
                     A : constant Action_Access := Action (Pkg, Without (Name, Suffix));
                  begin
                     return
                       (if Suffix = "_SendGoal_Request" then A.Send_Goal.Request
                        elsif Suffix = "_SendGoal_Response" then A.Send_Goal.Response
                        elsif Suffix = "_GetResult_Request" then A.Get_Result.Request
                        elsif Suffix = "_GetResult_Response" then A.Get_Result.Response
                        elsif Suffix = "_FeedbackMessage" then A.Feedback_Message
                        elsif Suffix = "_Goal" then A.Goal
                        elsif Suffix = "_Result" then A.Result
                        else A.Feedback);
                  end;
               end if;
            end loop;
         end if;
         raise Unknown_Type with
           "unknown message type " & Full_Name & ": expected 'package/msg/Name',"
           & " 'package/Name', 'package/srv/Name_Request' (or _Response) or"
           & " 'package/action/Name_<part>'";
      end;
   end Message;

   function Message_By_DDS_Name (DDS_Name : String) return Message_Access is
      Marker : constant String := "::dds_::";
      At_Marker : constant Natural := Ada.Strings.Fixed.Index (DDS_Name, Marker);
      First_Sep : constant Natural := Ada.Strings.Fixed.Index (DDS_Name, "::");
   begin
      if At_Marker = 0 or else First_Sep >= At_Marker
        or else DDS_Name (DDS_Name'Last) /= '_'
        or else At_Marker + Marker'Length > DDS_Name'Last - 1
      then
         raise Unknown_Type with
           "unknown DDS type name " & DDS_Name & ": expected 'package::msg::dds_::Name_'";
      end if;
      return Message
        (DDS_Name (DDS_Name'First .. First_Sep - 1) & "/"
         & DDS_Name (First_Sep + 2 .. At_Marker - 1) & "/"
         & DDS_Name (At_Marker + Marker'Length .. DDS_Name'Last - 1));
   end Message_By_DDS_Name;

   ---------------------------------------------------------------------------
   --  Listings

   --  Names, in order.
   function To_Vector (Names : Name_Sets.Set) return String_Vectors.Vector is
   begin
      return Result : String_Vectors.Vector do
         for N of Names loop
            Result.Append (N);
         end loop;
      end return;
   end To_Vector;

   function Packages return String_Vectors.Vector is
      use Ada.Directories;
      Names : Name_Sets.Set;

      procedure Take (E : Directory_Entry_Type) is
         Name : constant String := Simple_Name (E);
         Full : constant String := Full_Name (E);
      begin
         if ROSIDL.Parser.Is_Valid_Package_Name (Name)
           and then (Is_Folder (Full & "/msg") or else Is_Folder (Full & "/srv")
                     or else Is_Folder (Full & "/action"))
         then
            Names.Include (Name);
         end if;
      end Take;
   begin
      for Folder of Search_Path loop
         Search (Folder, "", [Directory => True, others => False], Take'Access);
      end loop;
      return To_Vector (Names);
   end Packages;

   function Listing (Package_Name, Kind : String) return String_Vectors.Vector is
      use Ada.Directories;
      Folder : constant String := Package_Folder (Package_Name);
      Names  : Name_Sets.Set;

      procedure Take (E : Directory_Entry_Type) is
         Name : constant String := Base_Name (Simple_Name (E));
      begin
         if ROSIDL.Parser.Is_Valid_Type_Name (Name) then
            Names.Include (Name);
         end if;
      end Take;
   begin
      if Folder = "" then
         raise Unknown_Type with
           "unknown interface package " & Package_Name & " on the interface search path "
           & Path_Image;
      end if;
      if Is_Folder (Folder & "/" & Kind) then
         Search (Folder & "/" & Kind, "*." & Kind, [Ordinary_File => True, others => False],
                 Take'Access);
      end if;
      return To_Vector (Names);
   end Listing;

   function Messages (Package_Name : String) return String_Vectors.Vector is
     (Listing (Package_Name, "msg"));
   function Services (Package_Name : String) return String_Vectors.Vector is
     (Listing (Package_Name, "srv"));
   function Actions (Package_Name : String) return String_Vectors.Vector is
     (Listing (Package_Name, "action"));

end ROSIDL.Interfaces;
