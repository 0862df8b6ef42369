--  The sancta-view command: reads the command line, starts the feeds and
--  opens the window, or takes one snapshot:
--
--     sancta-view --world office                      # the live window
--     sancta-view --world office --snapshot out/view.png --after 10
--
--  Exit status: 0, 1 on a runtime failure, 2 on a usage error.
procedure Sancta.Views.Main;
