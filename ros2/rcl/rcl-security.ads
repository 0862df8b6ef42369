--  DDS-Security the SROS2 way: which enclave of which keystore secures
--  this process's participant, from the environment variables ROS 2 uses
--
--     ROS_SECURITY_ENABLE=true           secure the participant
--     ROS_SECURITY_STRATEGY=Enforce      refuse to start without the files
--                                        (otherwise: warn, run unsecured)
--     ROS_SECURITY_KEYSTORE=DIR          an SROS2 keystore (Keystores)
--     ROS_SECURITY_ENCLAVE_OVERRIDE=/e   the enclave, over the one below
--
--  and the enclave named on the command line (--ros-args --enclave /e or
--  -e /e) or set by the program (Set_Enclave); "/" by default. The
--  enclave's files are DIR/enclaves/<enclave>/: identity_ca.cert.pem,
--  cert.pem, key.pem, permissions_ca.cert.pem, governance.p7s,
--  permissions.p7s (the names SROS2 and rmw_cyclonedds use); the
--  participant gets them as Cyclone's dds.sec.* properties with the
--  security plugins of Debian's libddsc0debian.
--  Example:
--     RCL.Security.Set_Enclave ("/team/r1");  --  before the first node
--     Node : RCL.Nodes.Node := RCL.Nodes.Init ("r1");  --  secured if enabled
with Ada.Strings.Unbounded;

package RCL.Security is

   use Ada.Strings.Unbounded;

   type Strategy is (Permissive, Enforce);

   type Settings is record
      Enabled  : Boolean := False;
      Mode     : Strategy := Permissive;
      Keystore : Unbounded_String;
      Enclave  : Unbounded_String := To_Unbounded_String ("/");
   end record;

   procedure Set_Enclave (Name : String)
     with Pre => Name'Length > 0 and then Name (Name'First) = '/';
   --  The enclave of this process when ROS_SECURITY_ENCLAVE_OVERRIDE is not
   --  set; takes effect when the participant is created.

   function Enclave return String;
   --  ROS_SECURITY_ENCLAVE_OVERRIDE, else Set_Enclave's, else the command
   --  line's --ros-args --enclave (-e) (RCL.Arguments), else "/".

   function Current return Settings;
   --  The environment's settings with Enclave. Raises ROS_Exception naming
   --  the variable when ROS_SECURITY_ENABLE or ROS_SECURITY_STRATEGY holds
   --  something else than true/false or Enforce/Permissive.

   type File_Kind is
     (Identity_CA, Certificate, Private_Key, Permissions_CA, Governance, Permissions);

   type Enclave_Files is array (File_Kind) of Unbounded_String;
   --  Absolute paths.

   function File_Name (Kind : File_Kind) return String;
   --  "identity_ca.cert.pem", "cert.pem", ... (SROS2's names).

   function Enclave_Directory (Keystore, Enclave : String) return String;
   --  Keystore/enclaves/<enclave without its leading "/">.

   type Credentials (Secured : Boolean := False) is record
      case Secured is
         when True  => Files : Enclave_Files;
         when False => null;
      end case;
   end record;
   --  How a participant is secured: not at all, or with an enclave's files.

   Unsecured : constant Credentials := (Secured => False);

   function Resolve (This : Settings) return Credentials;
   --  Secured with the enclave's files when enabled and all are there.
   --  Missing keystore, enclave or file: under Enforce raises ROS_Exception
   --  "SECURITY ERROR: ..." naming what is missing; under Permissive warns on
   --  standard error and returns Unsecured.

end RCL.Security;
