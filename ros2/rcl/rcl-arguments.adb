with Ada.Characters.Handling;
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with RCL.Names;

package body RCL.Arguments is

   use Ada.Strings.Unbounded;

   type Rule_Kind is (Any_Name, Topic_Only, Service_Only, Node_Rule, Namespace_Rule);

   type Remap_Rule is record
      Kind : Rule_Kind;
      Node : Unbounded_String;
      --  "" for every node.
      From : Unbounded_String;
      To   : Unbounded_String;
   end record;

   package Rule_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Remap_Rule);

   type Level_Setting is record
      Logger : Unbounded_String;
      --  "" for the default level.
      Level  : RCL.Logging.Severity;
   end record;

   package Level_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Level_Setting);

   type Parsed is record
      Rules        : Rule_Vectors.Vector;
      Levels       : Level_Vectors.Vector;
      Enclave      : Unbounded_String := To_Unbounded_String ("/");
      Parameters   : Argument_List;
      Rosout, Stdout : Boolean := True;
   end record;

   protected Current is
      procedure Set (P : Parsed; Was_Loaded : out Boolean; Only_If_Unloaded : Boolean);
      function Get return Parsed;
      function Is_Loaded return Boolean;
   private
      Value  : Parsed;
      Loaded : Boolean := False;
   end Current;

   protected body Current is
      procedure Set (P : Parsed; Was_Loaded : out Boolean; Only_If_Unloaded : Boolean) is
      begin
         Was_Loaded := Loaded;
         if not (Loaded and Only_If_Unloaded) then
            Value := P;
            Loaded := True;
         end if;
      end Set;
      function Get return Parsed is (Value);
      function Is_Loaded return Boolean is (Loaded);
   end Current;

   function Loaded return Boolean is (Current.Is_Loaded);

   function Quoted (Text : String) return String is ("'" & RCL.Names.Shortened (Text) & "'");
   --  An argument in a message (shortened: the reason stays within GNAT's
   --  200 characters of exception message).

   function Parse_Severity (Image : String) return RCL.Logging.Severity is
      Lower : constant String := Ada.Characters.Handling.To_Lower (Image);
   begin
      for S in RCL.Logging.Severity loop
         if Ada.Characters.Handling.To_Lower (S'Image) = Lower then
            return S;
         end if;
      end loop;
      raise Argument_Error with "unknown log level " & Quoted (Image)
        & " (debug, info, warn, error, fatal)";
   end Parse_Severity;

   --  "[node:]from:=to" into a rule; Where names the argument for errors.
   function Parse_Rule (Text, Where : String) return Remap_Rule is
      use Ada.Strings.Fixed;
      Sep : constant Natural := Index (Text, ":=");
      function Fail (Why : String) return Remap_Rule is
      begin
         raise Argument_Error with Where & " " & Quoted (Text) & ": " & Why;
         return (Any_Name, others => <>);
      end Fail;
   begin
      if Sep = 0 then
         return Fail ("expected from:=to");
      end if;
      declare
         Left  : constant String := Text (Text'First .. Sep - 1);
         To    : constant String := Text (Sep + 2 .. Text'Last);
         Colon : Natural := Index (Left, ":");
         Node  : Unbounded_String;
         From  : Unbounded_String;
         Kind  : Rule_Kind := Any_Name;
      begin
         --  "rostopic://x" and "rosservice://x" have a colon of their own.
         if Index (Left, "rostopic://") = Left'First
           or else Index (Left, "rosservice://") = Left'First
         then
            Colon := 0;
         end if;
         if Colon > 0 then
            Node := To_Unbounded_String (Left (Left'First .. Colon - 1));
            From := To_Unbounded_String (Left (Colon + 1 .. Left'Last));
            if RCL.Names.Node_Name_Problem (To_String (Node)) /= "" then
               return Fail (RCL.Names.Node_Name_Problem (To_String (Node)));
            end if;
         else
            From := To_Unbounded_String (Left);
         end if;
         declare
            F : constant String := To_String (From);
         begin
            if F = "" or else To = "" then
               return Fail ("expected from:=to with both names");
            elsif F = "__node" or else F = "__name" then
               if RCL.Names.Node_Name_Problem (To) /= "" then
                  return Fail (RCL.Names.Node_Name_Problem (To));
               end if;
               Kind := Node_Rule;
            elsif F = "__ns" then
               declare
                  NS : constant String := (if To (To'First) = '/' then To else "/" & To);
               begin
                  if RCL.Names.Namespace_Problem (NS) /= "" then
                     return Fail (RCL.Names.Namespace_Problem (NS));
                  end if;
                  return (Namespace_Rule, Node, From, To_Unbounded_String (NS));
               end;
            elsif F (F'First) = '_' and then F'Length > 1 and then F (F'First + 1) = '_' then
               return Fail ("unknown special name '" & F & "' (__node, __ns)");
            elsif Index (F, "rostopic://") = F'First then
               Kind := Topic_Only;
               From := To_Unbounded_String (F (F'First + 11 .. F'Last));
            elsif Index (F, "rosservice://") = F'First then
               Kind := Service_Only;
               From := To_Unbounded_String (F (F'First + 13 .. F'Last));
            elsif Index (F, "://") > 0 then
               return Fail ("unknown scheme (rostopic://, rosservice://)");
            end if;
            if Kind in Any_Name | Topic_Only | Service_Only then
               --  Validate both names as the names of some node would be.
               begin
                  declare
                     Ignored : constant String :=
                       RCL.Names.Expand_Topic_Name (To_String (From), "n", "/")
                       & RCL.Names.Expand_Topic_Name (To, "n", "/");
                  begin
                     null;
                  end;
               exception
                  when E : RCL.Names.Name_Error =>
                     return Fail (Ada.Exceptions.Exception_Message (E));
               end;
            end if;
            return (Kind, Node, From, To_Unbounded_String (To));
         end;
      end;
   end Parse_Rule;

   function Parameter_Override_Of (Text : String) return Parameter_Override is
      use Ada.Strings.Fixed;
      Sep   : constant Natural := Index (Text, ":=");
      Left  : constant String := (if Sep = 0 then "" else Text (Text'First .. Sep - 1));
      Colon : constant Natural := Index (Left, ":");
      Node  : constant String := (if Colon = 0 then "" else Left (Left'First .. Colon - 1));
      Name  : constant String := (if Colon = 0 then Left else Left (Colon + 1 .. Left'Last));
      Value : constant String := (if Sep = 0 then "" else Text (Sep + 2 .. Text'Last));
      Problem : constant String :=
        (if Sep = 0 or else Name = "" then "expected [node:]name:=value"
         elsif Colon > 0 and then RCL.Names.Node_Name_Problem (Node) /= ""
         then RCL.Names.Node_Name_Problem (Node)
         else RCL.Names.Parameter_Name_Problem (Name));
   begin
      if Problem /= "" then
         raise Argument_Error with Quoted (Text) & ": " & Problem;
      end if;
      return (Node'Length, Name'Length, Value'Length, Node, Name, Value);
   end Parameter_Override_Of;

   --  The same, with Where (the argument) in the message.
   procedure Check_Parameter_Rule (Text, Where : String) is
   begin
      declare
         Checked : constant Parameter_Override := Parameter_Override_Of (Text)
           with Unreferenced;
      begin
         null;
      end;
   exception
      when E : Argument_Error =>
         raise Argument_Error with Where & " " & Ada.Exceptions.Exception_Message (E);
   end Check_Parameter_Rule;

   function Do_Parse (Arguments : Argument_List) return Parsed is
      Result : Parsed;
      In_ROS : Boolean := False;
      I      : Positive := 1;
      N      : constant Natural := Natural (Arguments.Length);

      function Value_Of (Flag : String) return String is
      begin
         if I = N then
            raise Argument_Error with "--ros-args: " & Flag & " needs a value (argument"
              & I'Image & ")";
         end if;
         I := I + 1;
         return Arguments (I);
      end Value_Of;

      function Where return String is ("--ros-args: argument" & I'Image);
   begin
      while I <= N loop
         declare
            A : constant String := Arguments (I);
         begin
            if A = "--ros-args" then
               In_ROS := True;
            elsif not In_ROS then
               null;  --  The program's own.
            elsif A = "--" then
               In_ROS := False;
            elsif A in "-r" | "--remap" then
               declare
                  Text : constant String := Value_Of (A);
               begin
                  Result.Rules.Append (Parse_Rule (Text, Where));
               end;
            elsif A in "-p" | "--param" | "--params-file" then
               declare
                  Text : constant String := Value_Of (A);
               begin
                  if A /= "--params-file" then
                     Check_Parameter_Rule (Text, Where);
                  end if;
                  Result.Parameters.Append (A);
                  Result.Parameters.Append (Text);
               end;
            elsif A in "-e" | "--enclave" then
               declare
                  Text : constant String := Value_Of (A);
               begin
                  if RCL.Names.Namespace_Problem (Text) /= "" then
                     raise Argument_Error with Where & " " & Quoted (Text) & ": enclave "
                       & RCL.Names.Namespace_Problem (Text);
                  end if;
                  Result.Enclave := To_Unbounded_String (Text);
               end;
            elsif A = "--log-level" then
               declare
                  Text : constant String := Value_Of (A);
                  Sep  : constant Natural := Ada.Strings.Fixed.Index (Text, ":=");
               begin
                  if Sep = 0 then
                     Result.Levels.Append
                       (Level_Setting'(Null_Unbounded_String, Parse_Severity (Text)));
                  elsif Sep = Text'First then
                     raise Argument_Error with Where & " " & Quoted (Text)
                       & ": expected level or logger:=level";
                  else
                     Result.Levels.Append
                       (Level_Setting'(To_Unbounded_String (Text (Text'First .. Sep - 1)),
                         Parse_Severity (Text (Sep + 2 .. Text'Last))));
                  end if;
               exception
                  when E : Argument_Error =>
                     if Ada.Strings.Fixed.Index
                          (Ada.Exceptions.Exception_Message (E), "--ros-args") = 0
                     then
                        raise Argument_Error with Where & " " & Quoted (Text) & ": "
                          & Ada.Exceptions.Exception_Message (E);
                     end if;
                     raise;
               end;
            elsif A in "--enable-rosout-logs" | "--disable-rosout-logs" then
               Result.Rosout := A = "--enable-rosout-logs";
            elsif A in "--enable-stdout-logs" | "--disable-stdout-logs" then
               Result.Stdout := A = "--enable-stdout-logs";
            else
               raise Argument_Error with "--ros-args: unknown argument " & Quoted (A)
                 & " (argument" & I'Image & "; known: -r/--remap, -p/--param, --params-file, "
                 & "--log-level, -e/--enclave, --enable/--disable-rosout-logs, "
                 & "--enable/--disable-stdout-logs, --)";
            end if;
         end;
         I := I + 1;
      end loop;
      return Result;
   end Do_Parse;

   procedure Apply_Log_Levels is
      P : constant Parsed := Current.Get;
   begin
      for L of P.Levels loop
         if L.Logger = "" then
            RCL.Logging.Set_Level (L.Level);
         else
            RCL.Logging.Set_Logger_Level (To_String (L.Logger), L.Level);
         end if;
      end loop;
      RCL.Logging.Set_Console (P.Stdout);
   end Apply_Log_Levels;

   procedure Parse (Arguments : Argument_List) is
      Was : Boolean;
   begin
      Current.Set (Do_Parse (Arguments), Was, Only_If_Unloaded => False);
      Apply_Log_Levels;
   end Parse;

   procedure Load is
      Args : Argument_List;
      Was  : Boolean;
   begin
      if Current.Is_Loaded then
         return;
      end if;
      for I in 1 .. Ada.Command_Line.Argument_Count loop
         Args.Append (Ada.Command_Line.Argument (I));
      end loop;
      Current.Set (Do_Parse (Args), Was, Only_If_Unloaded => True);
      if not Was then
         Apply_Log_Levels;
      end if;
   end Load;

   --  Queries ----------------------------------------------------------------

   function Node_Name (Original : String) return String is
   begin
      for R of Current.Get.Rules loop
         if R.Kind = Node_Rule and then (R.Node = "" or else R.Node = Original) then
            return To_String (R.To);
         end if;
      end loop;
      return Original;
   end Node_Name;

   function Namespace (Node_Name : String; Original : String) return String is
   begin
      for R of Current.Get.Rules loop
         if R.Kind = Namespace_Rule and then (R.Node = "" or else R.Node = Node_Name) then
            return To_String (R.To);
         end if;
      end loop;
      return Original;
   end Namespace;

   function Remap
     (Name      : String;
      Kind      : Name_Kind;
      Node_Name : String;
      Namespace : String) return String is
   begin
      for R of Current.Get.Rules loop
         if (R.Kind = Any_Name
             or else (R.Kind = Topic_Only and Kind = Topic)
             or else (R.Kind = Service_Only and Kind = Service))
           and then (R.Node = "" or else R.Node = Node_Name)
           and then RCL.Names.Expand_Topic_Name (To_String (R.From), Node_Name, Namespace) = Name
         then
            return RCL.Names.Expand_Topic_Name (To_String (R.To), Node_Name, Namespace);
         end if;
      end loop;
      return Name;
   end Remap;

   function Enclave return String is (To_String (Current.Get.Enclave));

   procedure For_Each_Parameter_Argument
     (Process : not null access procedure (Flag, Value : String))
   is
      Args : Argument_List;
      I    : Positive := 1;
   begin
      Load;
      Args := Current.Get.Parameters;
      --  Pairs (flag, value), checked by Parse.
      while I < Natural (Args.Length) loop
         Process (Args (I), Args (I + 1));
         I := I + 2;
      end loop;
   end For_Each_Parameter_Argument;

   function Rosout_Enabled return Boolean is (Current.Get.Rosout);
   function Stdout_Enabled return Boolean is (Current.Get.Stdout);

end RCL.Arguments;
