--  Component "watchdog": watches one key and acts when it is not stored
--  again within a timeout.
--
--     <component name="watchdog" timeout="2.0" action="alarm">
--       <requires data="watched" as="odometric_pose"/>
--       <provides data="alarm" as="pose_alarm"/>
--     </component>
--
--  Options: timeout (seconds, default 5.0), action (abort | alarm, default
--  abort), check (seconds between checks, default timeout / 4).
--  "abort" requests the shutdown of the program with a failure status;
--  "alarm" stores true in output "alarm" (types.boolean) when the key goes
--  stale and false when it is refreshed again. The timeout counts from the
--  watchdog's start until the first store.
package Sancta.Standard_Components.Watchdog is
   pragma Elaborate_Body;
end Sancta.Standard_Components.Watchdog;
