--  Tests of RCL.Zstd: files and messages round trip (a frame with and
--  without its content size, frames one after the other), and the errors
--  on truncated, empty and trailing-garbage input, with their byte offsets;
--  one-shot compression into and out of the caller's buffers.
with AUnit.Test_Suites;

package RCL.Zstd.Tests is

   function Suite return AUnit.Test_Suites.Access_Test_Suite;

end RCL.Zstd.Tests;
