with Ada.Calendar.Formatting;
with Ada.Containers.Generic_Array_Sort;
with Ada.Directories;
with Ada.Numerics.Discrete_Random;
with Ada.Text_IO;
with Interfaces;
with GNAT.OS_Lib;
with Interfaces.C.Strings;

package body RCL.Security.Keystores is

   package Dirs renames Ada.Directories;

   LF : constant Character := ASCII.LF;

   function Domains_XML (Indent : String) return String is
     ("<domains>" & LF & Indent & "  <id_range>" & LF
      & Indent & "    <min>0</min>" & LF & Indent & "    <max>230</max>" & LF
      & Indent & "  </id_range>" & LF & Indent & "</domains>");
   --  Every domain id Cyclone's security accepts (0 .. 230, as SROS2).

   Governance_XML : constant String :=
     "<?xml version=""1.0"" encoding=""UTF-8""?>" & LF
     & "<dds xmlns:xsi=""http://www.w3.org/2001/XMLSchema-instance"""
     & " xsi:noNamespaceSchemaLocation="""
     & "http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd"">" & LF
     & "  <domain_access_rules>" & LF
     & "    <domain_rule>" & LF
     & "      " & Domains_XML ("      ") & LF
     & "      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>"
     & LF
     & "      <enable_join_access_control>true</enable_join_access_control>" & LF
     & "      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>" & LF
     & "      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>" & LF
     & "      <rtps_protection_kind>SIGN</rtps_protection_kind>" & LF
     & "      <topic_access_rules>" & LF
     & "        <topic_rule>" & LF
     & "          <topic_expression>*</topic_expression>" & LF
     & "          <enable_discovery_protection>true</enable_discovery_protection>" & LF
     & "          <enable_liveliness_protection>true</enable_liveliness_protection>" & LF
     & "          <enable_read_access_control>true</enable_read_access_control>" & LF
     & "          <enable_write_access_control>true</enable_write_access_control>" & LF
     & "          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>" & LF
     & "          <data_protection_kind>ENCRYPT</data_protection_kind>" & LF
     & "        </topic_rule>" & LF
     & "      </topic_access_rules>" & LF
     & "    </domain_rule>" & LF
     & "  </domain_access_rules>" & LF
     & "</dds>" & LF;

   -----------
   -- Files --
   -----------

   procedure Write_File (Path, Text : String) is
      F : Ada.Text_IO.File_Type;
   begin
      Ada.Text_IO.Create (F, Ada.Text_IO.Out_File, Path);
      Ada.Text_IO.Put (F, Text);
      Ada.Text_IO.Close (F);
   exception
      when Ada.Text_IO.Name_Error | Ada.Text_IO.Use_Error =>
         raise ROS_Exception with "security: cannot write " & Path;
   end Write_File;

   procedure Make_Directory (Path : String) is
   begin
      Dirs.Create_Path (Path);
   exception
      when Dirs.Name_Error | Dirs.Use_Error =>
         raise ROS_Exception with "security: cannot create the directory " & Path;
   end Make_Directory;

   procedure Link (Target, Path : String) is
      --  Path becomes a symbolic link to Target (relative to Path's
      --  directory), replacing what was there.
      package CS renames Interfaces.C.Strings;
      function Symlink (Target, Path : CS.chars_ptr) return Interfaces.C.int
        with Import, Convention => C, External_Name => "symlink";
      T : CS.chars_ptr := CS.New_String (Target);
      P : CS.chars_ptr := CS.New_String (Path);
      Result : Interfaces.C.int;
      Ignored : Boolean;
      use type Interfaces.C.int;
   begin
      GNAT.OS_Lib.Delete_File (Path, Ignored);
      Result := Symlink (T, P);
      CS.Free (T);
      CS.Free (P);
      if Result /= 0 then
         raise ROS_Exception with "security: cannot link " & Path & " to " & Target;
      end if;
   end Link;

   function Up (Levels : Natural) return String is
     (if Levels = 0 then "" else "../" & Up (Levels - 1));

   function Depth (Enclave : String) return Positive is
      --  Directories between enclaves/ and the enclave's files: "/a/b" = 2.
      Count : Natural := 0;
   begin
      for C of Enclave loop
         if C = '/' then
            Count := Count + 1;
         end if;
      end loop;
      return Positive'Max (1, Count);
   end Depth;

   -------------
   -- openssl --
   -------------

   procedure OpenSSL (Args : String; Work_Dir : String) is
      --  Runs "openssl Args" (words separated by spaces, no quoting) and
      --  raises ROS_Exception with its output when it fails.
      use GNAT.OS_Lib;
      Program : GNAT.OS_Lib.String_Access := Locate_Exec_On_Path ("openssl");
      Arg_List : String_List_Access := Argument_String_To_List (Args);
      Log      : constant String := Work_Dir & "/.openssl.log";
      Success  : Boolean;
      Code     : Integer;
   begin
      if Program = null then
         Free (Arg_List);
         raise ROS_Exception with "security: the openssl command is not installed"
           & " (Debian package openssl)";
      end if;
      Spawn (Program.all, Arg_List.all, Log, Success, Code, Err_To_Out => True);
      Free (Program);
      Free (Arg_List);
      if not Success or else Code /= 0 then
         declare
            F    : Ada.Text_IO.File_Type;
            Text : Unbounded_String;
         begin
            Ada.Text_IO.Open (F, Ada.Text_IO.In_File, Log);
            while not Ada.Text_IO.End_Of_File (F) loop
               Append (Text, Ada.Text_IO.Get_Line (F) & " ");
            end loop;
            Ada.Text_IO.Close (F);
            Delete_File (Log, Success);
            raise ROS_Exception with "security: openssl " & Args & " failed: " & To_String (Text);
         end;
      end if;
      Delete_File (Log, Success);
   end OpenSSL;

   procedure Sign (Keystore, Document, Signed : String) is
      --  S/MIME (text, detached), as SROS2 signs governance and permissions.
   begin
      OpenSSL ("smime -sign -text -in " & Document & " -out " & Signed
               & " -signer " & Keystore & "/public/permissions_ca.cert.pem"
               & " -inkey " & Keystore & "/private/permissions_ca.key.pem",
               Dirs.Containing_Directory (Signed));
   end Sign;

   function Serial return String is
      --  A random 64-bit certificate serial number, "0x..." (hexadecimal).
      package Random_Bits is new Ada.Numerics.Discrete_Random (Interfaces.Unsigned_32);
      Gen    : Random_Bits.Generator;
      Digits_Of : constant String := "0123456789abcdef";
      Result : String (1 .. 18) := "0x" & [1 .. 16 => '0'];
      use type Interfaces.Unsigned_32;
   begin
      Random_Bits.Reset (Gen);
      for Half in 0 .. 1 loop
         declare
            V : Interfaces.Unsigned_32 := Random_Bits.Random (Gen);
         begin
            for I in reverse 1 .. 8 loop
               Result (2 + Half * 8 + I) := Digits_Of (Natural (V mod 16) + 1);
               V := V / 16;
            end loop;
         end;
      end loop;
      Result (3) := '1';  --  Positive and never zero.
      return Result;
   end Serial;

   procedure Request_Config (Path, Common_Name : String) is
   begin
      Write_File (Path, "[req]" & LF & "distinguished_name = dn" & LF & "prompt = no" & LF
                  & "[dn]" & LF & "CN = " & Common_Name & LF
                  & "[ca]" & LF & "basicConstraints = critical,CA:TRUE" & LF);
   end Request_Config;

   function Absolute (Dir : String) return String is
     (Dirs.Full_Name (Dir));

   procedure Check_Enclave_Name (Enclave : String) is
   begin
      if Enclave'Length < 2 or else Enclave (Enclave'First) /= '/' then
         raise ROS_Exception with "security: enclave name """ & Enclave
           & """: expected a path such as /talker";
      end if;
      for I in Enclave'Range loop
         if Enclave (I) not in 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' | '_' | '/'
           or else (Enclave (I) = '/' and then I > Enclave'First and then Enclave (I - 1) = '/')
         then
            raise ROS_Exception with "security: enclave name """ & Enclave
              & """: character" & Integer'Image (I - Enclave'First + 1)
              & " is not allowed (letters, digits, '_' and single '/' between parts)";
         end if;
      end loop;
      if Enclave (Enclave'Last) = '/' then
         raise ROS_Exception with "security: enclave name """ & Enclave & """ ends with '/'";
      end if;
   end Check_Enclave_Name;

   procedure Check_Keystore (Keystore : String) is
   begin
      if not Dirs.Exists (Keystore & "/public/ca.cert.pem")
        or else not Dirs.Exists (Keystore & "/enclaves/governance.p7s")
      then
         raise ROS_Exception with "security: " & Keystore
           & " is not a keystore (make one with create_keystore)";
      end if;
   end Check_Keystore;

   ---------------------
   -- Create_Keystore --
   ---------------------

   procedure Create_Keystore (Dir : String) is
   begin
      Make_Directory (Dir);
      declare
         Root : constant String := Absolute (Dir);
      begin
         Make_Directory (Root & "/public");
         Make_Directory (Root & "/private");
         Make_Directory (Root & "/enclaves");
         if not Dirs.Exists (Root & "/public/ca.cert.pem") then
            Request_Config (Root & "/private/.ca.cnf", "sros2CA");
            OpenSSL ("req -x509 -new -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes"
                     & " -keyout " & Root & "/private/ca.key.pem"
                     & " -out " & Root & "/public/ca.cert.pem -days 3650 -sha256"
                     & " -config " & Root & "/private/.ca.cnf -extensions ca",
                     Root & "/private");
            Dirs.Delete_File (Root & "/private/.ca.cnf");
         end if;
         Link ("ca.cert.pem", Root & "/public/identity_ca.cert.pem");
         Link ("ca.cert.pem", Root & "/public/permissions_ca.cert.pem");
         Link ("ca.key.pem", Root & "/private/identity_ca.key.pem");
         Link ("ca.key.pem", Root & "/private/permissions_ca.key.pem");
         if not Dirs.Exists (Root & "/enclaves/governance.p7s") then
            Write_File (Root & "/enclaves/governance.xml", Governance_XML);
            Sign (Root, Root & "/enclaves/governance.xml", Root & "/enclaves/governance.p7s");
         end if;
      end;
   end Create_Keystore;

   --------------------
   -- Create_Enclave --
   --------------------

   function Checked_Root (Keystore, Enclave : String) return String is
   begin
      Check_Enclave_Name (Enclave);
      Check_Keystore (Keystore);
      return Absolute (Keystore);
   end Checked_Root;
   --  The absolute path of Keystore, once Enclave's name and Keystore are checked.

   procedure Create_Enclave (Keystore, Enclave : String) is
      Root : constant String := Checked_Root (Keystore, Enclave);
      Dir  : constant String := Enclave_Directory (Root, Enclave);
      Back : constant String := Up (Depth (Enclave));
   begin
      Make_Directory (Dir);
      Request_Config (Dir & "/.request.cnf", Enclave);
      OpenSSL ("req -new -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes"
               & " -keyout " & Dir & "/key.pem -out " & Dir & "/.request.csr"
               & " -config " & Dir & "/.request.cnf", Dir);
      OpenSSL ("x509 -req -in " & Dir & "/.request.csr"
               & " -CA " & Root & "/public/identity_ca.cert.pem"
               & " -CAkey " & Root & "/private/identity_ca.key.pem"
               & " -set_serial " & Serial
               & " -days 3650 -sha256 -out " & Dir & "/cert.pem", Dir);
      Dirs.Delete_File (Dir & "/.request.cnf");
      Dirs.Delete_File (Dir & "/.request.csr");
      Link (Back & "../public/identity_ca.cert.pem", Dir & "/identity_ca.cert.pem");
      Link (Back & "../public/permissions_ca.cert.pem", Dir & "/permissions_ca.cert.pem");
      Link (Back & "governance.p7s", Dir & "/governance.p7s");
      Create_Permission (Keystore, Enclave, Default_Rules);
   end Create_Enclave;

   -----------------------
   -- Create_Permission --
   -----------------------

   function Escaped (S : String) return String is
      R : Unbounded_String;
   begin
      for C of S loop
         case C is
            when '<' => Append (R, "&lt;");
            when '>' => Append (R, "&gt;");
            when '&' => Append (R, "&amp;");
            when '"' => Append (R, "&quot;");
            when others => Append (R, C);
         end case;
      end loop;
      return To_String (R);
   end Escaped;

   function Permissions_Document (Enclave : String; Rules : Topic_Rules) return String is
      use Ada.Calendar;
      Today : constant Time := Formatting.Time_Of
        (Formatting.Year (Clock), Formatting.Month (Clock), Formatting.Day (Clock));
      function Stamp (T : Time) return String is
         Image : String := Formatting.Image (T);  --  "2026-11-24 00:00:00" (UTC)
      begin
         Image (11) := 'T';
         return Image;
      end Stamp;

      function Section (Allow : Boolean; Rules : Topic_Rules) return String is
         Result : Unbounded_String;
      begin
         for Kind in Access_Kind loop
            declare
               Topics : Unbounded_String;
            begin
               for R of Rules loop
                  if R.Allow = Allow and then R.Kind = Kind then
                     Append (Topics, "            <topic>" & Escaped (To_String (R.Topic))
                             & "</topic>" & LF);
                  end if;
               end loop;
               if Topics /= Null_Unbounded_String then
                  declare
                     Tag : constant String := (if Kind = Publish then "publish" else "subscribe");
                  begin
                     Append (Result, "        <" & Tag & ">" & LF & "          <topics>" & LF
                             & Topics & "          </topics>" & LF
                             & "        </" & Tag & ">" & LF);
                  end;
               end if;
            end;
         end loop;
         if Result = Null_Unbounded_String then
            return "";
         end if;
         declare
            Tag : constant String := (if Allow then "allow_rule" else "deny_rule");
         begin
            return "      <" & Tag & ">" & LF & "        " & Domains_XML ("        ") & LF
              & To_String (Result) & "      </" & Tag & ">" & LF;
         end;
      end Section;
      Has_Deny : constant Boolean := (for some R of Rules => not R.Allow);
      Deny_Reading : constant Boolean :=
        (for some R of Rules => not R.Allow and then R.Kind = Subscribe);
      First : Topic_Rules (1 .. Rules'Length + 2);
      Last  : Natural := 0;
      --  Cyclone lets a participant join a domain only when the first rule
      --  of its grant on that domain allows, and lets it create a topic only
      --  when the first rule naming the topic allows: with deny rules (which
      --  must come before the allow rules they carve out of, "*"), a first
      --  allow rule with ros_discovery_info (which SROS2 always allows) and,
      --  unless some reading is denied, every allowed subscription.
   begin
      for Kind in Access_Kind loop
         Last := Last + 1;
         First (Last) := (True, Kind, To_Unbounded_String ("ros_discovery_info"));
      end loop;
      if not Deny_Reading then
         for R of Rules loop
            if R.Allow and then R.Kind = Subscribe then
               Last := Last + 1;
               First (Last) := R;
            end if;
         end loop;
      end if;
      return "<?xml version=""1.0"" encoding=""UTF-8""?>" & LF
        & "<dds xmlns:xsi=""http://www.w3.org/2001/XMLSchema-instance"""
        & " xsi:noNamespaceSchemaLocation="""
        & "http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd"">" & LF
        & "  <permissions>" & LF
        & "    <grant name=""" & Escaped (Enclave) & """>" & LF
        & "      <subject_name>CN=" & Escaped (Enclave) & "</subject_name>" & LF
        & "      <validity>" & LF
        & "        <not_before>" & Stamp (Today) & "</not_before>" & LF
        & "        <not_after>" & Stamp (Today + 3650 * Duration'(86_400.0)) & "</not_after>" & LF
        & "      </validity>" & LF
        & (if Has_Deny then Section (Allow => True, Rules => First (1 .. Last)) else "")
        & Section (Allow => False, Rules => Rules)
        & Section (Allow => True, Rules => Rules)
        & "      <default>DENY</default>" & LF
        & "    </grant>" & LF
        & "  </permissions>" & LF
        & "</dds>" & LF;
   end Permissions_Document;

   procedure Create_Permission (Keystore, Enclave : String; Rules : Topic_Rules) is
      Root : constant String := Checked_Root (Keystore, Enclave);
      Dir  : constant String := Enclave_Directory (Root, Enclave);
   begin
      if not Dirs.Exists (Dir & "/cert.pem") then
         raise ROS_Exception with "security: no enclave """ & Enclave & """ in " & Keystore
           & " (make it with create_enclave)";
      end if;
      Write_File (Dir & "/permissions.xml", Permissions_Document (Enclave, Rules));
      Sign (Root, Dir & "/permissions.xml", Dir & "/permissions.p7s");
   end Create_Permission;

   -------------------
   -- List_Enclaves --
   -------------------

   function List_Enclaves (Keystore : String) return Name_List is
      Found : Name_List (1 .. 10_000);
      Count : Natural := 0;

      procedure Walk (Dir, Name : String) is
         Search : Dirs.Search_Type;
         Item   : Dirs.Directory_Entry_Type;
      begin
         if Name /= "" and then Dirs.Exists (Dir & "/cert.pem") and then Count < Found'Last then
            Count := Count + 1;
            Found (Count) := To_Unbounded_String (Name);
         end if;
         Dirs.Start_Search (Search, Dir, "", [Dirs.Directory => True, others => False]);
         while Dirs.More_Entries (Search) loop
            Dirs.Get_Next_Entry (Search, Item);
            declare
               Simple : constant String := Dirs.Simple_Name (Item);
            begin
               if Simple /= "." and then Simple /= ".." then
                  Walk (Dir & "/" & Simple, Name & "/" & Simple);
               end if;
            end;
         end loop;
         Dirs.End_Search (Search);
      end Walk;

      procedure Sort is new Ada.Containers.Generic_Array_Sort (Positive, Unbounded_String,
                                                                Name_List);
   begin
      if not Dirs.Exists (Keystore & "/enclaves") then
         raise ROS_Exception with "security: " & Keystore & " is not a keystore (no enclaves/)";
      end if;
      Walk (Keystore & "/enclaves", "");
      Sort (Found (1 .. Count));
      return Found (1 .. Count);
   end List_Enclaves;

end RCL.Security.Keystores;
