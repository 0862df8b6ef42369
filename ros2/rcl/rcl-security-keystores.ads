--  SROS2 keystores, made with the openssl command (Debian package openssl):
--  the layout, file names, governance and permissions documents of
--  `ros2 security`, so that either tool reads the other's keystores:
--
--     DIR/public/ca.cert.pem            self-signed CA (ECDSA P-256),
--        identity_ca.cert.pem, permissions_ca.cert.pem -> ca.cert.pem
--     DIR/private/ca.key.pem (+ identity_ca.key.pem, permissions_ca.key.pem)
--     DIR/enclaves/governance.xml, governance.p7s (S/MIME, signed by the
--        permissions CA): authentication required, discovery, liveliness
--        and data encrypted, read and write access controlled
--     DIR/enclaves/<enclave>/cert.pem (CN=<enclave>), key.pem,
--        permissions.xml, permissions.p7s, and links to the two CA
--        certificates and governance.p7s
--
--  Example:
--     Create_Keystore ("/tmp/ks");
--     Create_Enclave ("/tmp/ks", "/talker");   --  may use every topic
--     Create_Permission ("/tmp/ks", "/talker",
--        [(Allow => True, Kind => Publish, Topic => To_Unbounded_String ("rt/chatter"))]);
--
--  Failures (no openssl, a file that cannot be written, an enclave name
--  that is not a path) raise ROS_Exception saying what and where.
package RCL.Security.Keystores is

   procedure Create_Keystore (Dir : String);
   --  Creates Dir (and its parents) if need be; an existing CA and
   --  governance are kept.

   procedure Create_Enclave (Keystore, Enclave : String);
   --  A new key and certificate for Enclave, and permissions for every
   --  topic (Default_Rules). Enclave names are paths: "/team/r1".

   type Access_Kind is (Publish, Subscribe);

   type Topic_Rule is record
      Allow : Boolean := True;
      Kind  : Access_Kind := Publish;
      Topic : Unbounded_String;
      --  A DDS topic name or fnmatch expression: "rt/chatter", "rq/*", "*".
   end record;

   type Topic_Rules is array (Positive range <>) of Topic_Rule;

   Default_Rules : constant Topic_Rules :=
     [1 => (Allow => True, Kind => Publish, Topic => To_Unbounded_String ("*")),
      2 => (Allow => True, Kind => Subscribe, Topic => To_Unbounded_String ("*"))];

   procedure Create_Permission (Keystore, Enclave : String; Rules : Topic_Rules);
   --  Writes and signs the enclave's permissions: one grant for
   --  CN=<Enclave>, valid ten years from today, on domains 0 .. 230; its
   --  deny rules, then its allow rules; everything else denied. With deny
   --  rules, a first allow rule with ros_discovery_info and (unless some
   --  reading is denied) the allowed subscriptions: Cyclone refuses to join
   --  a participant whose grant starts with a deny rule, and to create a
   --  topic whose first rule denies.

   function Permissions_Document (Enclave : String; Rules : Topic_Rules) return String;
   --  The permissions.xml Create_Permission signs.

   type Name_List is array (Positive range <>) of Unbounded_String;

   function List_Enclaves (Keystore : String) return Name_List;
   --  Sorted names of the enclaves (directories under enclaves/ with a
   --  cert.pem).

end RCL.Security.Keystores;
