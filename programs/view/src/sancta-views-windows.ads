--  The live window (GtkAda): a tool bar (zoom, fit, follow a robot, scans,
--  trails, pause, load a mission, kill / revive a simulated robot) over
--  the drawing of Sancta.Views.Drawing, refreshed ten times a second from
--  Feeds.Scene_Store. Mouse: drag to pan, wheel to zoom.
--
--     Feeds.Start (...);
--     Windows.Run ((others => <>), Width => 1280, Height => 820);
--     Feeds.Stop;
with Ada.Strings.Unbounded;
with Sancta.Views.Drawing;

package Sancta.Views.Windows is

   type Window_Config is record
      Options    : Drawing.View_Options;
      Width      : Positive := 1280;
      Height     : Positive := 820;
      Describe   : Ada.Strings.Unbounded.Unbounded_String;
      --  A JSON file rewritten after each drawing (Drawing.Write_Description,
      --  in the window's coordinates); "" none.
      Quit_After : Duration := Duration'Last;
      --  Seconds; the window closes itself then (tests).
   end record;

   procedure Run (Config : Window_Config);
   --  Opens the window and returns when it is closed (or Ctrl-C, or
   --  Quit_After). Program_Error when no display can be opened.

end Sancta.Views.Windows;
