with Ada.Directories;
with Ada.Environment_Variables;
with Ada.Text_IO;
with RCL.Arguments;

package body RCL.Security is

   package Env renames Ada.Environment_Variables;

   protected Chosen is
      procedure Set (Name : String);
      function Get return String;
   private
      Value : Unbounded_String;
   end Chosen;

   protected body Chosen is
      procedure Set (Name : String) is
      begin
         Value := To_Unbounded_String (Name);
      end Set;

      function Get return String is (To_String (Value));
   end Chosen;

   procedure Set_Enclave (Name : String) is
   begin
      Chosen.Set (Name);
   end Set_Enclave;

   function Enclave return String is
      Override : constant String := Env.Value ("ROS_SECURITY_ENCLAVE_OVERRIDE", "");
   begin
      if Override /= "" then
         return Override;
      elsif Chosen.Get /= "" then
         return Chosen.Get;
      end if;
      RCL.Arguments.Load;  --  (Parsed once.)
      return RCL.Arguments.Enclave;
   end Enclave;

   function Current return Settings is
      Enable   : constant String := Env.Value ("ROS_SECURITY_ENABLE", "false");
      Strategy : constant String := Env.Value ("ROS_SECURITY_STRATEGY", "Permissive");
   begin
      if Enable not in "true" | "false" | "" then
         raise ROS_Exception with "ROS_SECURITY_ENABLE: expected true or false, found """
           & Enable & """";
      elsif Strategy not in "Enforce" | "Permissive" | "" then
         raise ROS_Exception with "ROS_SECURITY_STRATEGY: expected Enforce or Permissive, found """
           & Strategy & """";
      end if;
      return (Enabled  => Enable = "true",
              Mode     => (if Strategy = "Enforce" then Enforce else Permissive),
              Keystore => To_Unbounded_String (Env.Value ("ROS_SECURITY_KEYSTORE", "")),
              Enclave  => To_Unbounded_String (Enclave));
   end Current;

   function File_Name (Kind : File_Kind) return String is
     (case Kind is
         when Identity_CA    => "identity_ca.cert.pem",
         when Certificate    => "cert.pem",
         when Private_Key    => "key.pem",
         when Permissions_CA => "permissions_ca.cert.pem",
         when Governance     => "governance.p7s",
         when Permissions    => "permissions.p7s");

   function Enclave_Directory (Keystore, Enclave : String) return String is
      Relative : constant String :=
        (if Enclave'Length > 0 and then Enclave (Enclave'First) = '/'
         then Enclave (Enclave'First + 1 .. Enclave'Last) else Enclave);
   begin
      return Keystore & "/enclaves" & (if Relative = "" then "" else "/" & Relative);
   end Enclave_Directory;

   function Resolve (This : Settings) return Credentials is

      procedure Refuse (Why : String) is
      begin
         if This.Mode = Enforce then
            raise ROS_Exception with "SECURITY ERROR: " & Why
              & " (ROS_SECURITY_STRATEGY=Enforce)";
         end if;
         Ada.Text_IO.Put_Line
           (Ada.Text_IO.Standard_Error,
            "[WARN] security: " & Why & "; running unsecured (ROS_SECURITY_STRATEGY is not"
            & " Enforce)");
      end Refuse;

      Keystore : constant String := To_String (This.Keystore);
      Name     : constant String := To_String (This.Enclave);
      Files    : Enclave_Files;
   begin
      if not This.Enabled then
         return Unsecured;
      elsif Keystore = "" then
         Refuse ("ROS_SECURITY_ENABLE is true but ROS_SECURITY_KEYSTORE is not set");
         return Unsecured;
      elsif Name = "" or else Name (Name'First) /= '/' then
         Refuse ("enclave """ & Name & """: an enclave name starts with ""/""");
         return Unsecured;
      end if;
      declare
         Dir : constant String := Enclave_Directory (Keystore, Name);
      begin
         if not Ada.Directories.Exists (Dir) then
            Refuse ("no directory for enclave """ & Name & """ in keystore " & Keystore
                    & " (expected " & Dir & ")");
            return Unsecured;
         end if;
         for K in File_Kind loop
            declare
               Path : constant String := Dir & "/" & File_Name (K);
            begin
               if not Ada.Directories.Exists (Path) then
                  Refuse ("enclave """ & Name & """ lacks " & Path);
                  return Unsecured;
               end if;
               Files (K) := To_Unbounded_String (Ada.Directories.Full_Name (Path));
            end;
         end loop;
      end;
      return (Secured => True, Files => Files);
   end Resolve;

end RCL.Security;
