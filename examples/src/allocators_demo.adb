--  RCLAda's rclada_test_allocators with Ada storage pools: a node given a
--  GNAT.Debug_Pools pool (RCL.Allocators) receives laser scans of growing
--  sizes; what decoding them allocated (the scans' sequences, kept by the
--  subscription and grown as needed) is counted by the pool, which prints
--  its totals at the end: total allocated, logically deallocated, current
--  and high water mark.
--     allocators_demo
with Ada.Text_IO;
with GNAT.Debug_Pools;
with RCL.Nodes.Typed;
with RCL.Publishers;
with ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;

procedure Allocators_Demo is

   package Scans renames ROSIDL.Static.Sensor_Msgs.Messages.LaserScan;
   package Topics is new RCL.Nodes.Typed (Scans.Handling);

   Pool : aliased GNAT.Debug_Pools.Debug_Pool;

   Received : Natural := 0;

   procedure On_Scan
     (Node : in out RCL.Nodes.Node'Class;
      Msg  : Scans.Message;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node, Info);
   begin
      Received := Received + 1;
      Ada.Text_IO.Put_Line ("received a scan of" & Msg.Ranges.Length'Image & " ranges");
   end On_Scan;

begin
   declare
      Node : RCL.Nodes.Node := RCL.Nodes.Init
        ("allocators_demo", Options => (Pool => Pool'Unchecked_Access, others => <>));
      Pub  : constant RCL.Publishers.Publisher := Topics.Publish (Node, "/allocators_demo");
      Scan : Scans.Message;
      type Size_List is array (Positive range <>) of Natural;
      Sizes : constant Size_List := [100, 720, 2000, 720];
   begin
      Topics.Subscribe (Node, "/allocators_demo", On_Scan'Access);
      Node.Spin (During => 0.5);
      for Size of Sizes loop
         Scan.Ranges.Set_Length (Size);
         Topics.Publish (Pub, Scan);
         Node.Spin (During => 0.2);
      end loop;
   end;
   Ada.Text_IO.Put_Line ("received" & Received'Image & " scans; the node's pool:");
   GNAT.Debug_Pools.Print_Info_Stdout (Pool);
end Allocators_Demo;
