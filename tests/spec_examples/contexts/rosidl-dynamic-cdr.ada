with ROSIDL.CDR; use ROSIDL.CDR;
use ROSIDL.Dynamic;
