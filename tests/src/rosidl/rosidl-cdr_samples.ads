--  Named sample messages shared by the CDR tests, the cdr_tool program and
--  the Python interoperability test (tests/interop/test_cdr_interop.py
--  declares the same values with the cyclonedds package).
with Ada.Containers.Vectors;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with Ada.Streams; use Ada.Streams;
with ROSIDL.CDR; use ROSIDL.CDR;

package ROSIDL.CDR_Samples is

   Names : constant ROSIDL.Definitions.String_Vectors.Vector :=
     ["string_hi", "header", "laser_scan", "odometry", "occupancy_grid",
      "add_two_ints_request", "everything", "arrays", "texts", "doubles", "floats",
      "wstrings"];

   Test_Header : constant Request_Header :=
     (GUID => 16#0102_0304_0506_0708#, Sequence => 42);
   --  The request header of add_two_ints_request.

   procedure Use_Test_Interfaces;
   --  Adds tests/interfaces (cdr_test_msgs) to the search path, once; the
   --  folder is found from SANCTA_ROOT, else the current directory.

   procedure Use_User_Interfaces;
   --  Adds tests/data/user_interfaces (a user's own package) the same way.

   function Make (Name : String) return ROSIDL.Dynamic.Message;
   --  The sample called Name; Constraint_Error for an unknown name.

   function Is_Request (Name : String) return Boolean is
     (Name = "add_two_ints_request");
   --  Encoded with Test_Header.

   function Encode_Sample
     (Name : String; Order : Byte_Order := Little_Endian)
      return Ada.Streams.Stream_Element_Array;
   --  Make (Name) encoded (with Test_Header when Is_Request).

   package Support_Vectors is new Ada.Containers.Vectors
     (Positive, ROSIDL.Typesupport.Message_Support, ROSIDL.Typesupport."=");

   function All_Types return Support_Vectors.Vector;
   --  Every message type on the search path (bundled and test interfaces):
   --  messages, service requests and responses, and the parts of actions
   --  (goal, result, feedback, feedback message, send-goal and get-result
   --  requests and responses).

   function Random_Message
     (Support    : ROSIDL.Typesupport.Message_Support;
      Seed       : in out UInt64;
      ASCII_Text : Boolean := False) return ROSIDL.Dynamic.Message;
   --  A message of that type with random values (deterministic from Seed,
   --  which advances): sequences of 0 to 4 elements (within bounds),
   --  strings of up to 12 bytes 1 .. 255 (printable ASCII when ASCII_Text),
   --  wstrings of any code point, finite floats.

   function Hex (Data : Ada.Streams.Stream_Element_Array) return String;
   --  "0001000003000000..." (lower case, no separators).

   function From_Hex (Text : String) return Ada.Streams.Stream_Element_Array;
   --  The inverse of Hex; spaces are ignored; Constraint_Error when
   --  malformed.

end ROSIDL.CDR_Samples;
