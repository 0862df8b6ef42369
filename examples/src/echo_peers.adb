with Ada.Text_IO;
with RCL.Contexts;

package body Echo_Peers is

   procedure Spin_Until_Echoed (Node : in out RCL.Nodes.Node'Class; Count : Natural) is
   begin
      Ada.Text_IO.Put_Line ("ready");
      while (Count = Until_Stopped or else Echoed < Count)
        and then not RCL.Contexts.Is_Shutdown
      loop
         Node.Spin (Once => True, During => 0.5);
      end loop;
      Node.Spin (During => 0.3);
      Ada.Text_IO.Put_Line ("echoed" & Echoed'Image);
   end Spin_Until_Echoed;

end Echo_Peers;
