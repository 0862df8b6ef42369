with RCL.Allocators;
with GNAT.Debug_Pools;
