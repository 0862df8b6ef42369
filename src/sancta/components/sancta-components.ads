--  The standard components of SANCTA (logger, watchdog, copy, merge,
--  switch). Each child package registers its component with the factory
--  when it is elaborated; "with Sancta.Components.All_Standard;" in a
--  program to get them all.
package Sancta.Components is
   pragma Pure;
end Sancta.Components;
