with RCL.Services; use RCL.Services;
use type Interfaces.Integer_64;
