with Ada.Text_IO;

package body Echo_Peers is

   procedure Spin_Until_Echoed (Node : in out RCL.Nodes.Node'Class; Count : Natural) is
   begin
      Ada.Text_IO.Put_Line ("ready");
      while Echoed < Count loop
         Node.Spin (Once => True, During => 0.5);
      end loop;
      Node.Spin (During => 0.3);
   end Spin_Until_Echoed;

end Echo_Peers;
