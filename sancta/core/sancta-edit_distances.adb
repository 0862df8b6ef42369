with Ada.Characters.Handling;

package body Sancta.Edit_Distances is

   function Distance (A, B : String; Ignore_Case : Boolean := False) return Natural is
      use Ada.Characters.Handling;

      function Same (X, Y : Character) return Boolean is
        (X = Y or else (Ignore_Case and then To_Lower (X) = To_Lower (Y)));

      type Row is array (0 .. B'Length) of Natural;
      Previous, Current : Row;
      --  Previous (J): the distance between A's first I - 1 characters and
      --  B's first J; Current the same for A's first I.
   begin
      for J in Previous'Range loop
         Previous (J) := J;
      end loop;
      for I in 1 .. A'Length loop
         Current (0) := I;
         for J in 1 .. B'Length loop
            Current (J) := Natural'Min
              (Natural'Min (Previous (J) + 1, Current (J - 1) + 1),
               Previous (J - 1)
               + (if Same (A (A'First + I - 1), B (B'First + J - 1)) then 0 else 1));
         end loop;
         Previous := Current;
      end loop;
      return Previous (B'Length);
   end Distance;

end Sancta.Edit_Distances;
