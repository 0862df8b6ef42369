with Ada.Calendar.Formatting;
with Ada.Characters.Handling;
with Ada.Containers.Indefinite_Ordered_Sets;
with Ada.Containers.Ordered_Maps;
with Ada.Directories;
with Ada.Exceptions;
with Ada.IO_Exceptions;
with Ada.Streams.Stream_IO;
with Ada.Strings.Fixed;
with Ada.Strings.Maps;
with Ada.Text_IO;
with Interfaces.C.Strings;
with ROSIDL.Definitions.Rendering;
with ROSIDL.Interfaces;
with ROSIDL.YAML_Strings;
with RCL.Contexts;
with RCL.Names;
with RCL.SQLite;
with RCL.YAML;

package body RCL.Bags is

   use Interfaces;
   use ROSIDL.Definitions;

   LF : constant Character := ASCII.LF;

   function Trim (S : String) return String is
     (Ada.Strings.Fixed.Trim (S, Ada.Strings.Both));

   function Image (V : Unsigned_64) return String is (Trim (V'Image));
   function Row_Image (V : Integer_64) return String is (" " & Trim (V'Image));
   --  With a space before it, as 'Image of a positive number.

   function Strip_Trailing_Newlines (S : String) return String is
      Last : Natural := S'Last;
   begin
      while Last >= S'First and then S (Last) in LF | ASCII.CR loop
         Last := Last - 1;
      end loop;
      return S (S'First .. Last);
   end Strip_Trailing_Newlines;

   -----------------------------
   -- Message_Definition_Text --
   -----------------------------

   function Read_Whole (Path : String) return String is
      use Ada.Streams.Stream_IO;
      F : File_Type;
   begin
      Open (F, In_File, Path);
      declare
         Length : constant Natural := Natural (Size (F));
         Text   : String (1 .. Length);
      begin
         String'Read (Stream (F), Text);
         Close (F);
         return Text;
      end;
   end Read_Whole;

   function Own_Text (M : Message_Definition) return String is
      File : constant String := To_String (M.Position.File);
   begin
      --  The .msg file as written (rosbag2 stores the file), else the
      --  parsed definition rendered back.
      if M.Namespace = Msg and then File'Length > 4
        and then File (File'Last - 3 .. File'Last) = ".msg"
        and then Ada.Directories.Exists (File)
      then
         return Strip_Trailing_Newlines (Read_Whole (File));
      end if;
      return Strip_Trailing_Newlines (ROSIDL.Definitions.Rendering.Show (M, Expand => False));
   end Own_Text;

   function Message_Definition_Text (Type_Name : String) return String is
      package Name_Sets is new Ada.Containers.Indefinite_Ordered_Sets (String);
      Root   : constant Message_Access := ROSIDL.Interfaces.Message (Type_Name);
      Seen   : Name_Sets.Set;
      Result : Unbounded_String := To_Unbounded_String (Own_Text (Root.all));

      procedure Add_Nested (M : Message_Definition) is
      begin
         for F of M.Fields loop
            if F.Of_Type.Kind = Message_Kind
              and then not Seen.Contains (Full_Name (F.Of_Type.Nested.all))
            then
               Seen.Insert (Full_Name (F.Of_Type.Nested.all));
               Append (Result, LF & [1 .. 80 => '='] & LF & "MSG: "
                       & Full_Name (F.Of_Type.Nested.all) & LF
                       & Own_Text (F.Of_Type.Nested.all));
               Add_Nested (F.Of_Type.Nested.all);
            end if;
         end loop;
      end Add_Nested;
   begin
      Seen.Insert (Full_Name (Root.all));
      Add_Nested (Root.all);
      return To_String (Result);
   end Message_Definition_Text;

   ----------------------
   -- Offered_QoS_Text --
   ----------------------

   function Offered_QoS_Text (Profiles : Profile_Array) return String is
      use RCL.QoS;
      Result : Unbounded_String;

      function Time (Name : String; D : Duration; Unset_Is_Infinite : Boolean) return String is
      begin
         if D = Infinite or else (Unset_Is_Infinite and then D = Unset) then
            return "  " & Name & ":" & LF & "    sec: 2147483647" & LF
              & "    nsec: 4294967295" & LF;
         end if;
         declare
            Seconds : constant Long_Long_Integer := Long_Long_Integer (D - 0.5);
            Nano    : constant Long_Long_Integer :=
              Long_Long_Integer ((D - Duration (Seconds)) * 1_000_000_000);
         begin
            return "  " & Name & ":" & LF & "    sec:" & Seconds'Image & LF
              & "    nsec:" & Nano'Image & LF;
         end;
      end Time;
   begin
      for P of Profiles loop
         Append (Result,
                 "- history: "
                 & (case P.History is
                      when Middleware_Default => "0", when Keep_Last => "1",
                      when Keep_All => "2") & LF
                 & "  depth:" & (if P.History = Keep_Last then P.Depth'Image else " 0") & LF
                 & "  reliability: "
                 & (case P.Reliability is
                      when Middleware_Default => "0", when Reliable => "1",
                      when Best_Effort => "2") & LF
                 & "  durability: "
                 & (case P.Durability is
                      when Middleware_Default => "0", when Transient_Local => "1",
                      when Volatile => "2") & LF
                 & Time ("deadline", P.Deadline, True)
                 & Time ("lifespan", P.Lifespan, True)
                 & "  liveliness: "
                 & (case P.Liveliness is
                      when Middleware_Default => "0", when Automatic => "1",
                      when Manual_By_Topic => "3") & LF
                 & Time ("liveliness_lease_duration", P.Lease, True)
                 & "  avoid_ros_namespace_conventions: false" & LF);
      end loop;
      return To_String (Result);
   end Offered_QoS_Text;

   ------------------
   -- Playback_QoS --
   ------------------

   procedure Interpret_Offered
     (Offered : String; Result : out RCL.QoS.Profile; Problem : out Unbounded_String)
   is
      --  Playback_QoS's answer, and what is not understood ("" when all is;
      --  Result is then Default).
      use RCL.QoS;
      use RCL.YAML;
      All_Local : Boolean := True;
      Depth     : Natural := 0;
   begin
      Result := Default;
      Problem := Null_Unbounded_String;
      if Trim (Offered) = "" then
         return;
      end if;
      declare
         D : constant Document := Parse (Offered, "offered_qos_profiles");
      begin
         if D.Kind (D.Root) /= Sequence then
            Problem := To_Unbounded_String ("expected a sequence of QoS profiles");
            return;
         elsif D.Length (D.Root) = 0 then
            return;
         end if;
         for I in 1 .. D.Length (D.Root) loop
            declare
               P : constant Node := D.Item (D.Root, I);
               function Field (Key : String) return String is
                 (if D.Kind (P) = Mapping and then D.Find (P, Key) /= 0
                    and then D.Kind (D.Find (P, Key)) = Scalar
                  then D.Text (D.Find (P, Key)) else "");
               --  rosbag2 writes the policies as numbers (metadata version 8
               --  and before: Humble) or names (9 on: Jazzy).
               Reliability : constant String := Field ("reliability");
               Durability  : constant String := Field ("durability");
               Depth_Text  : constant String := Field ("depth");
               Known : constant String :=
                 " 0 1 2 3 4 system_default unknown best_available ";
               Where : constant String := "profile" & I'Image & ": ";
            begin
               if D.Kind (P) /= Mapping then
                  Problem := To_Unbounded_String (Where & "expected a mapping of policies");
                  return;
               elsif Ada.Strings.Fixed.Index (Known & "reliable best_effort ",
                                              " " & Reliability & " ") = 0
                 and then Reliability /= ""
               then
                  Problem := To_Unbounded_String
                    (Where & "reliability '" & RCL.Names.Shortened (Reliability)
                     & "' is no reliability policy");
                  return;
               elsif Ada.Strings.Fixed.Index (Known & "transient_local volatile ",
                                              " " & Durability & " ") = 0
                 and then Durability /= ""
               then
                  Problem := To_Unbounded_String
                    (Where & "durability '" & RCL.Names.Shortened (Durability)
                     & "' is no durability policy");
                  return;
               elsif Depth_Text /= ""
                 and then (Depth_Text'Length > 9
                           or else (for some C of Depth_Text => C not in '0' .. '9'))
               then
                  Problem := To_Unbounded_String
                    (Where & "depth '" & RCL.Names.Shortened (Depth_Text)
                     & "' is no number of messages");
                  return;
               end if;
               if Reliability in "2" | "best_effort" then
                  Result.Reliability := Best_Effort;
               end if;
               if Durability not in "1" | "transient_local" then
                  All_Local := False;
               end if;
               if Depth_Text /= "" then
                  Depth := Natural'Max (Depth, Natural'Value (Depth_Text));
               end if;
            end;
         end loop;
      end;
      if All_Local then
         Result.Durability := Transient_Local;
      end if;
      Result.Depth := (if Depth = 0 then 10 else Depth);
   exception
      when E : Parse_Error =>
         Problem := To_Unbounded_String (Ada.Exceptions.Exception_Message (E));
   end Interpret_Offered;

   function Playback_QoS (Offered : String) return RCL.QoS.Profile is
      Result  : RCL.QoS.Profile;
      Problem : Unbounded_String;
   begin
      Interpret_Offered (Offered, Result, Problem);
      return (if Problem = Null_Unbounded_String then Result else RCL.QoS.Default);
   end Playback_QoS;

   function Offered_QoS_Problem (Offered : String) return String is
      Result  : RCL.QoS.Profile;
      Problem : Unbounded_String;
   begin
      Interpret_Offered (Offered, Result, Problem);
      return To_String (Problem);
   end Offered_QoS_Problem;

   --  Writing -----------------------------------------------------------------------

   function File_Path (This : Bag_Writer; Index : Positive) return String is
     (Ada.Directories.Compose
        (To_String (This.Directory),
         Ada.Directories.Simple_Name (To_String (This.Directory)) & "_"
         & Trim (Natural'Image (Index - 1)) & ".mcap"));

   procedure Start_File (This : in out Bag_Writer) is
      Index : constant Positive := Natural (This.Files.Length) + 1;
   begin
      This.File.Create (File_Path (This, Index), Profile => "ros2", Library => "rclada",
                        Compression => This.Compression, Background => This.Background);
      This.Files.Append
        (File_Entry'(Name => To_Unbounded_String
                       (Ada.Directories.Simple_Name (File_Path (This, Index))),
                     First => 0, Last => 0, Count => 0, Storage => MCAP_Storage,
                     Whole_Zstd => False));
      This.Schema_Types.Clear;
      for T of This.Topics loop
         T.Channel := 0;
      end loop;
   end Start_File;

   procedure Ensure_Channel (This : in out Bag_Writer; Topic : Topic_Index) is
      T      : Topic_Entry renames This.Topics (Topic);
      Type_Name : constant String := To_String (T.Type_Name);
      Schema : RCL.MCAP.Schema_Id := 0;
      Meta   : RCL.MCAP.String_Maps.Map;
   begin
      if T.Channel /= 0 then
         return;
      end if;
      for I in 1 .. Natural (This.Schema_Types.Length) loop
         if This.Schema_Types (I) = Type_Name then
            Schema := RCL.MCAP.Schema_Id (I);
         end if;
      end loop;
      if Schema = 0 then
         declare
            function Text return String is
            begin
               return Message_Definition_Text (Type_Name);
            exception
               when others => return "";
            end Text;
         begin
            Schema := This.File.Add_Schema (Type_Name, "ros2msg", Text);
            This.Schema_Types.Append (Type_Name);
         end;
      end if;
      Meta.Include ("offered_qos_profiles", To_String (T.QoS_Text));
      T.Channel := This.File.Add_Channel (To_String (T.Name), Schema, "cdr", Meta);
   end Ensure_Channel;

   procedure Close_File (This : in out Bag_Writer) is
      --  The current file closed; with File_Compression, compressed whole
      --  (name.mcap.zstd, as rosbag2) and the uncompressed one deleted.
      Last : File_Entry renames This.Files (This.Files.Last_Index);
      Path : constant String := File_Path (This, This.Files.Last_Index);
   begin
      This.File.Close;
      if This.Mode = File_Compression then
         begin
            RCL.Zstd.Compress_File (Path, Path & ".zstd");
         exception
            when E : others =>
               raise Bag_Error with Path & ": cannot compress into " & Path & ".zstd: "
                 & Ada.Exceptions.Exception_Message (E);
         end;
         Ada.Directories.Delete_File (Path);
         Last.Name := Last.Name & ".zstd";
      end if;
   end Close_File;

   procedure Create
     (This         : in out Bag_Writer;
      Directory    : String;
      Compression  : RCL.MCAP.Compression_Kind := RCL.MCAP.Zstd;
      Max_Bytes    : Interfaces.Unsigned_64 := 0;
      Max_Duration : Duration := 0.0;
      Background   : Boolean := False;
      Mode         : Bag_Compression := No_Compression) is
   begin
      if Ada.Directories.Exists (Directory) then
         raise Bag_Error with Directory & ": the output directory exists already (choose "
           & "another with -o, or remove it)";
      end if;
      begin
         Ada.Directories.Create_Path (Directory);
      exception
         when others =>
            raise Bag_Error with Directory & ": cannot create the output directory";
      end;
      This.Directory := To_Unbounded_String (Directory);
      This.Compression := Compression;
      This.Background := Background;
      This.Mode := Mode;
      This.Max_Bytes := Max_Bytes;
      This.Max_Span := Time_Stamp (Max_Duration * 1_000_000_000);
      This.Files.Clear;
      This.Topics.Clear;
      This.Total := 0;
      Start_File (This);
      This.Open := True;
   end Create;

   function Is_Open (This : Bag_Writer) return Boolean is (This.Open);

   function Add_Topic
     (This : in out Bag_Writer; Name, Type_Name, Offered_QoS : String) return Topic_Index is
   begin
      This.Topics.Append
        (Topic_Entry'(Name     => To_Unbounded_String (Name),
                      Type_Name => To_Unbounded_String (Type_Name),
                      QoS_Text => To_Unbounded_String (Offered_QoS),
                      Count    => 0, Channel => 0, Schema => 0, File => 0,
                      Channel_At | Schema_At => 0, Row => 0));
      Ensure_Channel (This, This.Topics.Last_Index);
      return This.Topics.Last_Index;
   end Add_Topic;

   procedure Write
     (This         : in out Bag_Writer;
      Topic        : Topic_Index;
      Receive_Time : Time_Stamp;
      Data         : RCL.MCAP.Byte_Array;
      Publish_Time : Time_Stamp := 0)
   is
   begin
      declare
         Current : constant File_Entry := This.Files.Last_Element;
      begin
         if Current.Count > 0
           and then ((This.Max_Bytes > 0 and then This.File.Bytes_Written >= This.Max_Bytes)
                     or else (This.Max_Span > 0
                              and then Receive_Time >= Current.First
                              and then Receive_Time - Current.First >= This.Max_Span))
         then
            Close_File (This);
            Start_File (This);
         end if;
      end;
      Ensure_Channel (This, Topic);
      if This.Mode = Message_Compression then
         declare
            procedure Put (Frame : RCL.MCAP.Byte_Array) is
            begin
               This.File.Write (This.Topics (Topic).Channel, Receive_Time, Frame,
                                Publish_Time => Publish_Time);
            end Put;
         begin
            This.Zipper.Compress (Data, Put'Access);
         end;
      else
         This.File.Write (This.Topics (Topic).Channel, Receive_Time, Data,
                          Publish_Time => Publish_Time);
      end if;
      declare
         Current : File_Entry renames This.Files (This.Files.Last_Index);
         T       : Topic_Entry renames This.Topics (Topic);
      begin
         if Current.Count = 0 or else Receive_Time < Current.First then
            Current.First := Receive_Time;
         end if;
         Current.Last := Time_Stamp'Max (Current.Last, Receive_Time);
         Current.Count := Current.Count + 1;
         T.Count := T.Count + 1;
      end;
      This.Total := This.Total + 1;
   end Write;

   function Message_Count (This : Bag_Writer) return Unsigned_64 is (This.Total);
   function File_Count (This : Bag_Writer) return Natural is (Natural (This.Files.Length));

   procedure Write_Metadata (This : Bag_Writer) is
      use Ada.Text_IO;
      F      : File_Type;
      First  : Time_Stamp := Time_Stamp'Last;
      Last   : Time_Stamp := 0;
   begin
      for E of This.Files loop
         if E.Count > 0 then
            First := Time_Stamp'Min (First, E.First);
            Last := Time_Stamp'Max (Last, E.Last);
         end if;
      end loop;
      if This.Total = 0 then
         First := 0;
      end if;
      Create (F, Out_File, Ada.Directories.Compose (To_String (This.Directory), "metadata.yaml"));
      Put_Line (F, "rosbag2_bagfile_information:");
      Put_Line (F, "  version: 5");
      Put_Line (F, "  storage_identifier: mcap");
      Put_Line (F, "  duration:");
      Put_Line (F, "    nanoseconds: " & Image (if This.Total = 0 then 0 else Last - First));
      Put_Line (F, "  starting_time:");
      Put_Line (F, "    nanoseconds_since_epoch: " & Image (First));
      Put_Line (F, "  message_count: " & Image (This.Total));
      Put_Line (F, "  topics_with_message_count:");
      for T of This.Topics loop
         Put_Line (F, "    - topic_metadata:");
         Put_Line (F, "        name: " & To_String (T.Name));
         Put_Line (F, "        type: " & To_String (T.Type_Name));
         Put_Line (F, "        serialization_format: cdr");
         Put_Line (F, "        offered_qos_profiles: "
                   & ROSIDL.YAML_Strings.Double_Quoted (To_String (T.QoS_Text)));
         Put_Line (F, "      message_count: " & Image (T.Count));
      end loop;
      case This.Mode is
         when No_Compression =>
            Put_Line (F, "  compression_format: """"");
            Put_Line (F, "  compression_mode: """"");
         when File_Compression =>
            Put_Line (F, "  compression_format: zstd");
            Put_Line (F, "  compression_mode: FILE");
         when Message_Compression =>
            Put_Line (F, "  compression_format: zstd");
            Put_Line (F, "  compression_mode: MESSAGE");
      end case;
      Put_Line (F, "  relative_file_paths:");
      for E of This.Files loop
         Put_Line (F, "    - " & To_String (E.Name));
      end loop;
      Put_Line (F, "  files:");
      for E of This.Files loop
         Put_Line (F, "    - path: " & To_String (E.Name));
         Put_Line (F, "      starting_time:");
         Put_Line (F, "        nanoseconds_since_epoch: " & Image (E.First));
         Put_Line (F, "      duration:");
         Put_Line (F, "        nanoseconds: " & Image (E.Last - E.First));
         Put_Line (F, "      message_count: " & Image (E.Count));
      end loop;
      Close (F);
   end Write_Metadata;

   procedure Close (This : in out Bag_Writer) is
   begin
      if This.Open then
         This.Open := False;
         Close_File (This);
         Write_Metadata (This);
      end if;
   end Close;

   overriding procedure Finalize (This : in out Bag_Writer) is
   begin
      Close (This);
   exception
      when others => null;
   end Finalize;

   --  Reading ---------------------------------------------------------------------

   function Find_Topic (Topics : Topic_Vectors.Vector; Name : String) return Topic_Index'Base is
   begin
      for I in Topics.First_Index .. Topics.Last_Index loop
         if Topics (I).Name = Name then
            return I;
         end if;
      end loop;
      return 0;
   end Find_Topic;

   function Listed_Files
     (Directory : String; Warning : out Unbounded_String; Mode : out Compression_Mode)
      return Type_Vectors.Vector
   is
      use Ada.Directories;
      Result : Type_Vectors.Vector;
      Meta   : constant String := Compose (Directory, "metadata.yaml");
   begin
      Warning := Null_Unbounded_String;
      Mode := Not_Said;
      if Exists (Meta) then
         begin
            declare
               use RCL.YAML;
               D     : constant Document := Parse_File (Meta);
               Info  : constant Natural := D.Find (D.Root, "rosbag2_bagfile_information");
               Paths : constant Natural :=
                 (if Info /= 0 then D.Find (Info, "relative_file_paths") else 0);
               function Field (Key : String) return String is
                  --  compression_mode or _format: "" when absent or empty.
                  N : constant Natural := (if Info /= 0 then D.Find (Info, Key) else 0);
               begin
                  if N = 0 or else D.Kind (N) = Null_Value then
                     return "";
                  elsif D.Kind (N) /= Scalar then
                     raise Bag_Error with D.Where (N) & ": " & Key
                       & ": expected a word (file, message, zstd...)";
                  end if;
                  return Ada.Characters.Handling.To_Lower (D.Text (N));
               end Field;
               Mode_Text   : constant String := Field ("compression_mode");
               Format_Text : constant String := Field ("compression_format");
               Mode_At     : constant String :=
                 (if Info /= 0 and then D.Find (Info, "compression_mode") /= 0
                  then D.Where (D.Find (Info, "compression_mode")) else Meta);
            begin
               if Mode_Text = ""
                 and then (Info = 0 or else D.Find (Info, "compression_mode") = 0)
               then
                  Mode := Not_Said;
               elsif Mode_Text in "" | "none" then
                  Mode := None_Said;
               elsif Mode_Text = "file" then
                  Mode := File_Said;
               elsif Mode_Text = "message" then
                  Mode := Message_Said;
               else
                  raise Bag_Error with Mode_At & ": compression_mode '"
                    & RCL.Names.Shortened (Mode_Text) & "': expected file, message or none";
               end if;
               if Mode in File_Said | Message_Said and then Format_Text /= "zstd" then
                  raise Bag_Error with
                    (if D.Find (Info, "compression_format") /= 0
                     then D.Where (D.Find (Info, "compression_format")) else Meta)
                    & ": compression_format '" & RCL.Names.Shortened (Format_Text)
                    & "' (compression_mode " & Mode_Text & "): only zstd is read";
               end if;
               if Paths /= 0 then
                  for I in 1 .. D.Length (Paths) loop
                     Result.Append (Compose (Directory, Simple_Name (D.Text (D.Item (Paths, I)))));
                  end loop;
               end if;
            end;
         exception
            when E : RCL.YAML.Parse_Error =>
               --  A metadata.yaml this reader cannot parse: list the files,
               --  and say so.
               Result.Clear;
               Mode := Not_Said;
               Warning := To_Unbounded_String
                 (Ada.Exceptions.Exception_Message (E)
                  & " (metadata.yaml not understood: the directory's .mcap or .db3 files are"
                  & " read)");
         end;
      end if;
      if Result.Is_Empty then
         declare
            package Sorting is new Type_Vectors.Generic_Sorting;
            Search : Search_Type;
            Item   : Directory_Entry_Type;
         begin
            for Extension in 1 .. 4 loop
               --  .mcap files (or compressed whole: .mcap.zstd), else .db3.
               exit when not Result.Is_Empty and then Extension = 3;
               Start_Search (Search, Directory,
                             (case Extension is
                                 when 1 => "*.mcap", when 2 => "*.mcap.zstd",
                                 when 3 => "*.db3", when others => "*.db3.zstd"),
                             [Ordinary_File => True, others => False]);
               while More_Entries (Search) loop
                  Get_Next_Entry (Search, Item);
                  Result.Append (Full_Name (Item));
               end loop;
               End_Search (Search);
            end loop;
            Sorting.Sort (Result);
         end;
      end if;
      return Result;
   end Listed_Files;

   --  rosbag2's sqlite3 storage ------------------------------------------------------

   function Starts_With (Path, Header : String) return Boolean is
      use Ada.Streams.Stream_IO;
      F     : File_Type;
      Start : String (Header'Range);
   begin
      Open (F, In_File, Path);
      if Size (F) < Header'Length then
         Close (F);
         return False;
      end if;
      String'Read (Stream (F), Start);
      Close (F);
      return Start = Header;
   exception
      when others =>
         if Is_Open (F) then
            Close (F);
         end if;
         return False;
   end Starts_With;

   function Is_SQLite_File (Path : String) return Boolean is
     (Starts_With (Path, "SQLite format 3" & ASCII.NUL));
   --  The database header, whatever the file's name.

   function Is_Zstd_File (Path : String) return Boolean is
     (Starts_With (Path, [Character'Val (16#28#), Character'Val (16#B5#),
                          Character'Val (16#2F#), Character'Val (16#FD#)]));
   --  A Zstandard frame: rosbag2's compression_mode file (bag_0.db3.zstd).

   function Place_Of (Path : String; Whole : Boolean) return String is
     (RCL.Names.Shortened (Path, 80, 57) & (if Whole then " (decompressed)" else ""));
   --  A file's name in errors about what it holds; for one compressed whole,
   --  a byte offset after it counts in the decompressed data.

   function File_Place (This : Bag_Reader; File : Positive) return String is
     (Place_Of (To_String (This.Files (File).Name), This.Files (File).Whole_Zstd));

   --  Files compressed whole (rosbag2's compression_mode file) ---------------------

   function Temporary_File (Hint : String) return String is
      --  A new empty file of ours in $TMPDIR (else /tmp), made by mkstemp:
      --  no other process's file is overwritten.
      use Interfaces.C;
      function Mkstemp (Template : Strings.chars_ptr) return int
        with Import, Convention => C, External_Name => "mkstemp";
      function C_Close (Fd : int) return int
        with Import, Convention => C, External_Name => "close";
      function Get_Env (Name : String) return String is
         function C_Getenv (Name : Strings.chars_ptr) return Strings.chars_ptr
           with Import, Convention => C, External_Name => "getenv";
         N : Strings.chars_ptr := Strings.New_String (Name);
         V : constant Strings.chars_ptr := C_Getenv (N);
      begin
         Strings.Free (N);
         return (if Strings."=" (V, Strings.Null_Ptr) then "" else Strings.Value (V));
      end Get_Env;
      Folder   : constant String := (if Get_Env ("TMPDIR") /= "" then Get_Env ("TMPDIR")
                                     else "/tmp");
      Template : Strings.chars_ptr :=
        Strings.New_String (Folder & "/rclada-" & Hint & "-XXXXXX");
      Fd       : constant int := Mkstemp (Template);
      Name     : constant String := Strings.Value (Template);
      Ignored  : int;
   begin
      Strings.Free (Template);
      if Fd < 0 then
         raise Bag_Error with Name & ": cannot create a temporary file to decompress into"
           & " (set TMPDIR to a writable folder)";
      end if;
      Ignored := C_Close (Fd);
      return Name;
   end Temporary_File;

   procedure Close (This : in out Bag_Reader) is
   begin
      if This.Plain_File /= 0 then
         This.Plain_File := 0;
         if Ada.Directories.Exists (To_String (This.Plain_Path)) then
            Ada.Directories.Delete_File (To_String (This.Plain_Path));
         end if;
      end if;
   end Close;

   overriding procedure Finalize (This : in out Bag_Reader) is
   begin
      Close (This);
   exception
      when others => null;
   end Finalize;

   procedure Expand (This : in out Bag_Reader; Path : String; File : Positive) is
      --  Path (the bag's File-th file, compressed whole) decompressed into
      --  a temporary file, unless it is there already: one at a time.
      Simple : constant String := Ada.Directories.Simple_Name (Path);
      Hint   : constant String :=
        Ada.Strings.Fixed.Translate
          (Simple (Simple'First .. Simple'First - 1 + Natural'Min (Simple'Length, 40)),
           Ada.Strings.Maps.To_Mapping (" /", "__"));
   begin
      if This.Plain_File = File then
         return;
      end if;
      Close (This);
      This.Plain_Path := To_Unbounded_String (Temporary_File (Hint));
      This.Plain_File := File;
      RCL.Zstd.Decompress_File (Path, To_String (This.Plain_Path),
                                Label => RCL.Names.Shortened (Path, 80, 57),
                                Stop  => RCL.Contexts.Is_Shutdown'Access);
   exception
      when E : RCL.Zstd.Interrupted =>
         Close (This);
         raise Bag_Error with Ada.Exceptions.Exception_Message (E) & " (shut down: a signal)";
      when E : RCL.Zstd.Zstd_Error =>
         Close (This);
         raise Bag_Error with Ada.Exceptions.Exception_Message (E);
      when E : Ada.IO_Exceptions.Use_Error | Ada.IO_Exceptions.Device_Error =>
         Close (This);
         raise Bag_Error with RCL.Names.Shortened (Path, 80, 57) & ": cannot decompress into "
           & To_String (This.Plain_Path) & ": " & Ada.Exceptions.Exception_Message (E)
           & " (full disk? set TMPDIR)";
   end Expand;

   function Readable (This : Bag_Reader; Path : String; Whole : Boolean) return String is
     (if Whole then To_String (This.Plain_Path) else Path);
   --  The file to open for Path: itself, or its decompressed copy.

   package Id_Maps is new Ada.Containers.Ordered_Maps (Integer_64, Topic_Index);
   --  A .db3 file's topics.id to the reader's topic.

   procedure Check_Tables (DB : RCL.SQLite.Database; Place : String) is
      --  The tables and columns rosbag2's sqlite3 storage has at every
      --  schema version (offered_qos_profiles from version 2 on is optional).
      procedure Need_Table (Table : String) is
      begin
         if not DB.Table_Exists (Table) then
            raise Bag_Error with Place & ": no table '" & Table
              & "' (a SQLite database, but no rosbag2 sqlite3 bag)";
         end if;
      end Need_Table;

      procedure Need_Column (Table, Column : String) is
      begin
         if not DB.Has_Column (Table, Column) then
            raise Bag_Error with Place & ": table " & Table & " has no column '"
              & Column & "' (a rosbag2 sqlite3 bag has)";
         end if;
      end Need_Column;
   begin
      Need_Table ("topics");
      Need_Table ("messages");
      Need_Column ("topics", "id");
      Need_Column ("topics", "name");
      Need_Column ("topics", "type");
      Need_Column ("topics", "serialization_format");
      Need_Column ("messages", "id");
      Need_Column ("messages", "topic_id");
      Need_Column ("messages", "timestamp");
      Need_Column ("messages", "data");
   end Check_Tables;

   procedure Open_SQLite (This : in out Bag_Reader; Path, Name : String; Whole : Boolean) is
      --  Path: the database; Name: the bag's file (Path, or the file
      --  compressed whole that Path was decompressed from).
      use RCL.SQLite;
      Place  : constant String := Place_Of (Name, Whole);
      File   : constant Positive := Natural (This.Files.Length) + 1;
      DB     : Database;
      Ids    : Id_Maps.Map;
      Entry_Of_File : File_Entry :=
        (Name => To_Unbounded_String (Name), Storage => SQLite_Storage, Whole_Zstd => Whole,
         others => <>);
   begin
      DB.Open_Read_Only (Path, Label => Place);
      Check_Tables (DB, Place);
      declare
         Has_QoS : constant Boolean := DB.Has_Column ("topics", "offered_qos_profiles");
         S       : Statement;
      begin
         S.Prepare (DB, "SELECT rowid, id, name, type, serialization_format"
                    & (if Has_QoS then ", offered_qos_profiles" else ", NULL")
                    & " FROM topics ORDER BY rowid");
         while S.Step loop
            declare
               Row   : constant Integer_64 := S.Int (0);
               Where : constant String := Place & ": topics row" & Row_Image (Row);
               procedure Expect (Column : Natural; Name : String; Kind : Value_Kind) is
               begin
                  if S.Kind (Column) /= Kind then
                     raise Bag_Error with Where & ": " & Name & " is "
                       & Kind_Name (S.Kind (Column)) & ", expected " & Kind_Name (Kind);
                  end if;
               end Expect;
            begin
               Expect (1, "id", Integer_Value);
               Expect (2, "name", Text_Value);
               Expect (3, "type", Text_Value);
               Expect (4, "serialization_format", Text_Value);
               if S.Kind (5) not in Text_Value | Null_Value then
                  Expect (5, "offered_qos_profiles", Text_Value);
               end if;
               declare
                  Id      : constant Integer_64 := S.Int (1);
                  Name    : constant String := S.Text (2);
                  Of_Type : constant String := S.Text (3);
                  Format  : constant String := S.Text (4);
                  Found   : Topic_Index'Base := Find_Topic (This.Topics, Name);

                  function Topic_Was return String is
                    --  Where the topic was first: this file's row, or
                    --  another file's row or channel record.
                    (if This.Topics (Found).File = File
                     then "in topics row" & Row_Image (This.Topics (Found).Row)
                     elsif This.Files (This.Topics (Found).File).Storage = SQLite_Storage
                     then "in " & Ada.Directories.Simple_Name
                       (To_String (This.Files (This.Topics (Found).File).Name))
                       & " topics row" & Row_Image (This.Topics (Found).Row)
                     else "in " & Ada.Directories.Simple_Name
                       (To_String (This.Files (This.Topics (Found).File).Name))
                       & " on channel" & This.Topics (Found).Channel'Image);
               begin
                  if Ids.Contains (Id) then
                     raise Bag_Error with Where & ": id" & Row_Image (Id)
                       & " is another row's too";
                  elsif Format /= "cdr" then
                     raise Bag_Error with Where & ": topic '" & RCL.Names.Shortened (Name)
                       & "': serialization_format '" & RCL.Names.Shortened (Format)
                       & "' (only cdr is read)";
                  elsif Found /= 0 and then This.Topics (Found).Type_Name /= Of_Type then
                     raise Bag_Error with Where & ": topic '" & RCL.Names.Shortened (Name)
                       & "' is '" & RCL.Names.Shortened (Of_Type) & "' here, '"
                       & RCL.Names.Shortened (To_String (This.Topics (Found).Type_Name))
                       & "' " & Topic_Was;
                  elsif Found = 0 then
                     This.Topics.Append
                       (Topic_Entry'(Name      => To_Unbounded_String (Name),
                                     Type_Name => To_Unbounded_String (Of_Type),
                                     QoS_Text  => To_Unbounded_String
                                       (if S.Kind (5) = Text_Value then S.Text (5) else ""),
                                     Count     => 0, Channel => 0, Schema => 0,
                                     File      => File,
                                     Channel_At | Schema_At => 0,
                                     Row       => Row));
                     Found := This.Topics.Last_Index;
                  end if;
                  Ids.Insert (Id, Found);
               end;
            end;
         end loop;
      end;
      declare
         --  The first row that cannot be played, in one pass.
         S : Statement;
      begin
         S.Prepare (DB, "SELECT rowid, typeof (topic_id), typeof (timestamp), typeof (data),"
                    & " topic_id, timestamp, CASE WHEN length (data) > 0 THEN data END"
                    & " FROM messages"
                    & " WHERE typeof (topic_id) <> 'integer' OR typeof (timestamp) <> 'integer'"
                    & " OR typeof (data) <> 'blob' OR length (data) = 0 OR timestamp < 0"
                    & " OR topic_id NOT IN (SELECT id FROM topics)"
                    & (if This.Mode = Message_Said
                       then " OR substr (data, 1, 4) <> X'28B52FFD'" else "")
                    & " ORDER BY rowid LIMIT 1");
         if S.Step then
            declare
               Where : constant String := Place & ": messages row" & Row_Image (S.Int (0)) & ": ";
            begin
               if S.Text (1) /= "integer" then
                  raise Bag_Error with Where & "topic_id is " & S.Text (1)
                    & ", expected integer";
               elsif S.Text (2) /= "integer" then
                  raise Bag_Error with Where & "timestamp is " & S.Text (2)
                    & ", expected integer";
               elsif S.Text (3) /= "blob" then
                  raise Bag_Error with Where & "data is " & S.Text (3) & ", expected blob";
               elsif S.Int (5) < 0 then
                  raise Bag_Error with Where & "timestamp" & Row_Image (S.Int (5))
                    & " is negative (nanoseconds since 1970)";
               elsif not Ids.Contains (S.Int (4)) then
                  raise Bag_Error with Where & "topic_id" & Row_Image (S.Int (4))
                    & " names no topic";
               elsif This.Mode = Message_Said and then S.Kind (6) = Blob_Value then
                  raise Bag_Error with Where & "data is no zstd frame, but metadata.yaml says"
                    & " compression_mode message";
               end if;
               raise Bag_Error with Where & "data is empty (0 bytes; a CDR message has 4 or"
                 & " more)";
            end;
         end if;
      end;
      declare
         S : Statement;
      begin
         S.Prepare (DB, "SELECT topic_id, count (*), min (timestamp), max (timestamp)"
                    & " FROM messages GROUP BY topic_id");
         while S.Step loop
            declare
               T     : Topic_Entry renames This.Topics (Ids (S.Int (0)));
               Count : constant Unsigned_64 := Unsigned_64 (S.Int (1));
               First : constant Time_Stamp := Time_Stamp (S.Int (2));
               Last  : constant Time_Stamp := Time_Stamp (S.Int (3));
            begin
               T.Count := T.Count + Count;
               if Entry_Of_File.Count = 0 or else First < Entry_Of_File.First then
                  Entry_Of_File.First := First;
               end if;
               Entry_Of_File.Last := Time_Stamp'Max (Entry_Of_File.Last, Last);
               Entry_Of_File.Count := Entry_Of_File.Count + Count;
            end;
         end loop;
      end;
      if Entry_Of_File.Count > 0 then
         if This.Total = 0 or else Entry_Of_File.First < This.First then
            This.First := Entry_Of_File.First;
         end if;
         This.Last := Time_Stamp'Max (This.Last, Entry_Of_File.Last);
      end if;
      This.Total := This.Total + Entry_Of_File.Count;
      This.Size := This.Size + Unsigned_64 (Ada.Directories.Size (Name));
      This.Files.Append (Entry_Of_File);
   exception
      when E : SQLite_Error =>
         raise Bag_Error with Ada.Exceptions.Exception_Message (E);
   end Open_SQLite;

   procedure Iterate_SQLite
     (This    : in out Bag_Reader;
      Path    : String;
      Process : not null access procedure
        (Topic : Topic_Index; Receive_Time : Time_Stamp; Data : RCL.MCAP.Byte_Array))
   is
      --  The file This.Now_File, which Open_SQLite checked (Path: the
      --  database, decompressed if the file is compressed whole).
      use RCL.SQLite;
      Place : constant String := File_Place (This, This.Now_File);
      DB    : Database;
      Ids   : Id_Maps.Map;
   begin
      DB.Open_Read_Only (Path, Label => Place);
      declare
         S : Statement;
      begin
         S.Prepare (DB, "SELECT id, name FROM topics");
         while S.Step loop
            Ids.Include (S.Int (0), Find_Topic (This.Topics, S.Text (1)));
         end loop;
      end;
      declare
         S : Statement;
         Topic : Topic_Index'Base;
         Stamp : Integer_64;
         procedure Each (Data : Ada.Streams.Stream_Element_Array) is
         begin
            Process (Topic, Time_Stamp (Stamp), Data);
         end Each;
      begin
         S.Prepare (DB, "SELECT rowid, topic_id, timestamp, data FROM messages"
                    & " ORDER BY timestamp, rowid");
         while S.Step loop
            This.Now_Row := S.Int (0);
            Stamp := S.Int (2);
            Topic := (if Ids.Contains (S.Int (1)) then Ids (S.Int (1)) else 0);
            if Topic = 0 or else Stamp < 0 then
               --  Open_SQLite checked every row: the file changed since.
               raise Bag_Error with Place & ": messages row" & Row_Image (This.Now_Row)
                 & ": topic_id" & Row_Image (S.Int (1)) & " or timestamp" & Row_Image (Stamp)
                 & " is not what the file held when opened (changed since?)";
            end if;
            S.Blob (3, Each'Access);
         end loop;
      end;
   exception
      when E : SQLite_Error =>
         raise Bag_Error with Ada.Exceptions.Exception_Message (E);
   end Iterate_SQLite;

   procedure Open (This : in out Bag_Reader; Path : String; Recover : Boolean := False) is
      use Ada.Directories;
      Paths : Type_Vectors.Vector;
   begin
      This.Files.Clear;
      This.Topics.Clear;
      This.Total := 0;
      This.First := 0;
      This.Last := 0;
      This.Size := 0;
      This.Recover := Recover;
      This.Compression := Null_Unbounded_String;
      This.Warning := Null_Unbounded_String;
      This.Mode := Not_Said;
      Close (This);
      if not Exists (Path) then
         raise Bag_Error with Path & ": no such bag (directory or .mcap file)";
      elsif Kind (Path) = Directory then
         Paths := Listed_Files (Path, This.Warning, This.Mode);
         if Paths.Is_Empty then
            raise Bag_Error with Path & ": no .mcap or .db3 file in this directory";
         end if;
      else
         Paths.Append (Path);
      end if;
      for P of Paths loop
         if not Exists (P) then
            raise Bag_Error with P & ": listed in metadata.yaml but missing";
         end if;
         declare
            File  : constant Positive := Natural (This.Files.Length) + 1;
            Whole : constant Boolean := Is_Zstd_File (P);
         begin
            if This.Mode = File_Said and then not Whole then
               raise Bag_Error with RCL.Names.Shortened (P, 80, 57) & ": byte 0: no zstd frame"
                 & " (expected 28 B5 2F FD), but metadata.yaml says compression_mode file";
            elsif Whole then
               Expand (This, P, File);
               if Size (To_String (This.Plain_Path)) = 0 then
                  raise Bag_Error with RCL.Names.Shortened (P, 80, 57) & ": decompresses to 0"
                    & " bytes: no MCAP or SQLite file inside";
               end if;
            end if;
            if Is_SQLite_File (Readable (This, P, Whole)) then
               Open_SQLite (This, Readable (This, P, Whole), P, Whole);
               goto Next_File;
            end if;
            This.Current.Open (Readable (This, P, Whole), Recover,
                               Label => Place_Of (P, Whole));
         end;
         This.Size := This.Size + Unsigned_64 (Size (P));
         if This.Compression = Null_Unbounded_String then
            This.Compression := To_Unbounded_String (This.Current.Compression);
         end if;
         for I in 1 .. This.Current.Channel_Count loop
            declare
               C     : constant RCL.MCAP.Channel_Info := This.Current.Channel (I);
               Found : Topic_Index'Base := Find_Topic (This.Topics, To_String (C.Topic));
               Qos   : constant String :=
                 (if C.Metadata.Contains ("offered_qos_profiles")
                  then C.Metadata.Element ("offered_qos_profiles") else "");
               Of_Type : constant Unbounded_String :=
                 (if C.Schema = 0 then Null_Unbounded_String
                  else This.Current.Find_Schema (C.Schema).Name);
            begin
               if Found /= 0 and then This.Topics (Found).Type_Name /= Of_Type then
                  --  One topic, one type: played with one, the other
                  --  messages would be misread.
                  raise Bag_Error with RCL.Names.Shortened (P, 80, 57) & ": byte "
                    & Image (This.Current.Channel_Offset (I)) & ": channel" & C.Id'Image
                    & ": topic '" & RCL.Names.Shortened (To_String (C.Topic)) & "' is '"
                    & RCL.Names.Shortened (To_String (Of_Type)) & "' here, '"
                    & RCL.Names.Shortened (To_String (This.Topics (Found).Type_Name)) & "' "
                    & (if This.Topics (Found).File = Natural (This.Files.Length) + 1 then ""
                       else "in " & Ada.Directories.Simple_Name
                         (To_String (This.Files (This.Topics (Found).File).Name)) & " ")
                    & "on channel" & This.Topics (Found).Channel'Image;
               elsif Found = 0 then
                  This.Topics.Append
                    (Topic_Entry'(Name      => C.Topic,
                                  Type_Name => Of_Type,
                                  QoS_Text  => To_Unbounded_String (Qos),
                                  Count     => 0, Channel => C.Id, Schema => C.Schema,
                                  File      => Natural (This.Files.Length) + 1,
                                  Channel_At => This.Current.Channel_Offset (I),
                                  Schema_At  => (if C.Schema = 0 then 0
                                                 else This.Current.Schema_Offset (C.Schema)),
                                  Row        => 0));
                  Found := This.Topics.Last_Index;
               end if;
               This.Topics (Found).Count :=
                 This.Topics (Found).Count + This.Current.Channel_Message_Count (C.Id);
            end;
         end loop;
         if This.Current.Message_Count > 0 then
            if This.Total = 0 or else This.Current.Start_Time < This.First then
               This.First := This.Current.Start_Time;
            end if;
            This.Last := Time_Stamp'Max (This.Last, This.Current.End_Time);
         end if;
         This.Total := This.Total + This.Current.Message_Count;
         This.Files.Append (File_Entry'(Name  => To_Unbounded_String (P),
                                        First => This.Current.Start_Time,
                                        Last  => This.Current.End_Time,
                                        Count => This.Current.Message_Count,
                                        Storage => MCAP_Storage,
                                        Whole_Zstd => Is_Zstd_File (P)));
         This.Current.Close;
         <<Next_File>>
      end loop;
   end Open;

   function Topic_Count (This : Bag_Reader) return Natural is (Natural (This.Topics.Length));
   function Topic_Name (This : Bag_Reader; Topic : Topic_Index) return String is
     (To_String (This.Topics (Topic).Name));
   function Topic_Type (This : Bag_Reader; Topic : Topic_Index) return String is
     (To_String (This.Topics (Topic).Type_Name));
   function Topic_QoS (This : Bag_Reader; Topic : Topic_Index) return String is
     (To_String (This.Topics (Topic).QoS_Text));
   function Topic_Message_Count (This : Bag_Reader; Topic : Topic_Index) return Unsigned_64 is
     (This.Topics (Topic).Count);

   function Topic_Place (This : Bag_Reader; Topic : Topic_Index) return String is
     (if This.Files (This.Topics (Topic).File).Storage = SQLite_Storage
      then File_Place (This, This.Topics (Topic).File) & ": topics row"
        & Row_Image (This.Topics (Topic).Row)
      else File_Place (This, This.Topics (Topic).File) & ": byte "
        & Image (This.Topics (Topic).Channel_At) & ": channel"
        & This.Topics (Topic).Channel'Image);

   function Type_Place (This : Bag_Reader; Topic : Topic_Index) return String is
     (if This.Topics (Topic).Schema = 0
        or else This.Files (This.Topics (Topic).File).Storage = SQLite_Storage
      then Topic_Place (This, Topic)
      else File_Place (This, This.Topics (Topic).File) & ": byte "
        & Image (This.Topics (Topic).Schema_At) & ": schema" & This.Topics (Topic).Schema'Image);

   function Message_Place (This : Bag_Reader) return String is
     (if This.Files (This.Now_File).Storage = SQLite_Storage
      then File_Place (This, This.Now_File) & ": messages row" & Row_Image (This.Now_Row)
      else File_Place (This, This.Now_File) & ": " & RCL.MCAP.Readers.Place (This.Now_Message));

   function Message_Count (This : Bag_Reader) return Unsigned_64 is (This.Total);
   function Start_Time (This : Bag_Reader) return Time_Stamp is (This.First);
   function End_Time (This : Bag_Reader) return Time_Stamp is (This.Last);
   function File_Count (This : Bag_Reader) return Natural is (Natural (This.Files.Length));
   function File_Name (This : Bag_Reader; Index : Positive) return String is
     (To_String (This.Files (Index).Name));
   function Bytes (This : Bag_Reader) return Unsigned_64 is (This.Size);
   function Compression (This : Bag_Reader) return String is (To_String (This.Compression));
   function Warning (This : Bag_Reader) return String is (To_String (This.Warning));

   procedure Iterate
     (This    : in out Bag_Reader;
      Process : not null access procedure
        (Topic : Topic_Index; Receive_Time : Time_Stamp; Data : RCL.MCAP.Byte_Array))
   is
      procedure Deliver
        (Topic : Topic_Index; Receive_Time : Time_Stamp; Data : RCL.MCAP.Byte_Array) is
         --  Data to Process, decompressed first when it is a zstd frame
         --  (compression_mode message; a CDR message starts with 00).
         procedure Give (Plain : RCL.MCAP.Byte_Array) is
         begin
            Process (Topic, Receive_Time, Plain);
         end Give;
      begin
         if RCL.Zstd.Starts_Frame (Data) then
            begin
               This.Unzstd.Decompress (Data, Give'Access);
            exception
               when E : RCL.Zstd.Zstd_Error =>
                  raise Bag_Error with Message_Place (This) & ": data: "
                    & Ada.Exceptions.Exception_Message (E);
            end;
         elsif This.Mode = Message_Said then
            raise Bag_Error with Message_Place (This) & ": data is no zstd frame, but"
              & " metadata.yaml says compression_mode message";
         else
            Process (Topic, Receive_Time, Data);
         end if;
      end Deliver;
   begin
      for File in This.Files.First_Index .. This.Files.Last_Index loop
         This.Now_File := File;
         if This.Files (File).Whole_Zstd then
            Expand (This, To_String (This.Files (File).Name), File);
         end if;
         if This.Files (File).Storage = SQLite_Storage then
            Iterate_SQLite (This, Readable (This, To_String (This.Files (File).Name),
                                            This.Files (File).Whole_Zstd), Deliver'Access);
            goto Next_File;
         end if;
         This.Current.Open (Readable (This, To_String (This.Files (File).Name),
                                      This.Files (File).Whole_Zstd), This.Recover,
                            Label => File_Place (This, File));
         declare
            type Topic_Map is array (RCL.MCAP.Channel_Id range <>) of Topic_Index'Base;
            Largest : RCL.MCAP.Channel_Id := 0;
         begin
            for I in 1 .. This.Current.Channel_Count loop
               Largest := RCL.MCAP.Channel_Id'Max (Largest, This.Current.Channel (I).Id);
            end loop;
            declare
               Map : Topic_Map (0 .. Largest) := [others => 0];
               procedure Each (Msg : RCL.MCAP.Readers.Message; Data : RCL.MCAP.Byte_Array) is
               begin
                  This.Now_Message := Msg;
                  if Msg.Channel not in Map'Range or else Map (Msg.Channel) = 0 then
                     --  Open read every channel record of the file: this one
                     --  was not there then.
                     raise RCL.MCAP.Format_Error with Message_Place (This)
                       & ": message on channel" & Msg.Channel'Image
                       & ", which the file did not define when opened: corrupt";
                  end if;
                  Deliver (Map (Msg.Channel), Msg.Log_Time, Data);
               end Each;
            begin
               for I in 1 .. This.Current.Channel_Count loop
                  declare
                     C : constant RCL.MCAP.Channel_Info := This.Current.Channel (I);
                  begin
                     Map (C.Id) := Find_Topic (This.Topics, To_String (C.Topic));
                  end;
               end loop;
               This.Current.Iterate (Each'Access);
            end;
         end;
         This.Current.Close;
         <<Next_File>>
      end loop;
   end Iterate;

   ----------
   -- Info --
   ----------

   function Info (This : Bag_Reader) return String is
      function Size_Image (Bytes : Unsigned_64) return String is
         function Fixed (X : Long_Float) return String is
            Hundredths : constant Long_Long_Integer := Long_Long_Integer (X * 100.0);
            Frac       : constant String := Trim (Long_Long_Integer'Image (Hundredths mod 100));
         begin
            return Trim (Long_Long_Integer'Image (Hundredths / 100)) & "."
              & (if Frac'Length = 1 then "0" & Frac else Frac);
         end Fixed;
      begin
         if Bytes < 1024 then
            return Image (Bytes) & " B";
         elsif Bytes < 1024 * 1024 then
            return Fixed (Long_Float (Bytes) / 1024.0) & " KiB";
         elsif Bytes < 1024 * 1024 * 1024 then
            return Fixed (Long_Float (Bytes) / 1024.0 / 1024.0) & " MiB";
         end if;
         return Fixed (Long_Float (Bytes) / 1024.0 / 1024.0 / 1024.0) & " GiB";
      end Size_Image;

      function Seconds (T : Time_Stamp) return String is
         Frac : constant String := Image (T mod 1_000_000_000);
      begin
         return Image (T / 1_000_000_000) & "." & [1 .. 9 - Frac'Length => '0'] & Frac;
      end Seconds;

      function Date (T : Time_Stamp) return String is
         use Ada.Calendar;
         Epoch : constant Time := Formatting.Time_Of (1970, 1, 1, 0.0);
      begin
         return Formatting.Image (Epoch + Duration (T / 1_000_000_000)) & " UTC ("
           & Seconds (T) & ")";
      exception
         when others => return Seconds (T);
      end Date;

      Pad    : constant String := [1 .. 19 => ' '];
      Result : Unbounded_String;
      Width  : Natural := 0;
      Type_Width : Natural := 0;
   begin
      Append (Result, LF & "Files:             ");
      for I in 1 .. This.File_Count loop
         Append (Result, (if I > 1 then Pad else "")
                 & Ada.Directories.Simple_Name (This.File_Name (I)) & LF);
      end loop;
      Append (Result, "Bag size:          " & Size_Image (This.Size) & LF);
      Append (Result, "Storage id:        "
              & (if not This.Files.Is_Empty
                   and then This.Files.First_Element.Storage = SQLite_Storage
                 then "sqlite3" else "mcap") & LF);
      Append (Result, "Duration:          " & Seconds (This.Last - This.First) & "s" & LF);
      Append (Result, "Start:             " & Date (This.First) & LF);
      Append (Result, "End:               " & Date (This.Last) & LF);
      Append (Result, "Messages:          " & Image (This.Total) & LF);
      declare
         SQLite : constant Boolean :=
           not This.Files.Is_Empty and then This.Files.First_Element.Storage = SQLite_Storage;
         Chunks : constant String :=
           (if SQLite then ""
            elsif This.Compression = Null_Unbounded_String then "none (chunks)"
            else To_String (This.Compression) & " (chunks)");
         Rosbag2 : constant String :=
           --  rosbag2's own: of files or messages.
           (if (for some F of This.Files => F.Whole_Zstd) then "zstd (file)"
            elsif This.Mode = Message_Said then "zstd (message)"
            else "");
      begin
         Append (Result, "Compression:       "
                 & (if Rosbag2 /= "" and then Chunks /= "" then Rosbag2 & ", " & Chunks
                    elsif Rosbag2 /= "" then Rosbag2
                    elsif SQLite then "none"
                    else Chunks) & LF);
      end;
      for T of This.Topics loop
         Width := Natural'Max (Width, Length (T.Name));
         Type_Width := Natural'Max (Type_Width, Length (T.Type_Name));
      end loop;
      Append (Result, "Topic information: ");
      if This.Topics.Is_Empty then
         Append (Result, LF);
      end if;
      for I in This.Topics.First_Index .. This.Topics.Last_Index loop
         declare
            T : Topic_Entry renames This.Topics (I);
         begin
            Append (Result, (if I > This.Topics.First_Index then Pad else "")
                    & "Topic: " & To_String (T.Name) & [1 .. Width - Length (T.Name) => ' ']
                    & " | Type: " & To_String (T.Type_Name)
                    & [1 .. Type_Width - Length (T.Type_Name) => ' ']
                    & " | Count: " & Image (T.Count) & " | Serialization Format: cdr" & LF);
         end;
      end loop;
      return To_String (Result);
   end Info;

end RCL.Bags;
