with RCL.Parameters; use RCL.Parameters;
--  DECLARATIONS
Rate : Long_Long_Integer;
function Check (Name : String; New_Value : Value) return String is ("");
