--  The edit (Levenshtein) distance between two strings, for the "did you
--  mean ...?" suggestions of the commands and of the configuration reader
--  (the rclada CLI's type names, Sancta.Runtime.Factory's component names).
--  Neutral text code in the lowest SANCTA layer, so that both may use it;
--  the ROS 2 library does not.
--
--     Edit_Distances.Distance ("kitten", "sitting") = 3
--     Edit_Distances.Distance ("Logger", "logger", Ignore_Case => True) = 0
package Sancta.Edit_Distances
  with Pure
is

   function Distance (A, B : String; Ignore_Case : Boolean := False) return Natural
     with Global => null,
          Post   => Distance'Result >= abs (A'Length - B'Length)
                    and then Distance'Result <= Natural'Max (A'Length, B'Length);
   --  The fewest insertions, deletions and substitutions of one character
   --  that turn A into B (Latin-1 case folded with Ignore_Case). Time
   --  A'Length * B'Length, memory one row of B'Length + 1 on the stack: a
   --  caller facing names of any length compares only those whose length
   --  differs by no more than it would accept (the distance is at least that
   --  difference).

end Sancta.Edit_Distances;
