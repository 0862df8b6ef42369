with ROSIDL.Static.Example_Interfaces.Services.AddTwoInts;
