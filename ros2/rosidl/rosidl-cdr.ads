--  The CDR wire encoding of ROS 2 messages (XCDR1, as rmw_cyclonedds_cpp
--  writes it): Encode, Decode, the request/reply header. The package is
--  ROSIDL.Dynamic.CDR (see it for the rules); this name is the one programs
--  use. It is a renaming so that the codec working on the storage of
--  dynamic messages can be a private child of ROSIDL.Dynamic.
with ROSIDL.Dynamic.CDR;

package ROSIDL.CDR renames ROSIDL.Dynamic.CDR;
