with Ada.Exceptions;
with Ada.Text_IO;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;
with RCL.Contexts;
with RCL.Graph;
with RCL.DDS;
with RCL.Logging;
with RCL.Process_Context;
with RCL.QoS;

package body RCL.Rosout is

   type Writer_Access is access RCL.DDS.Writer;

   Support : ROSIDL.Typesupport.Message_Support;
   Writer  : Writer_Access;

   --  Serializes publications, and drops records logged while one is being
   --  published by the same path (no recursion).
   protected Gate is
      procedure Enter (Ok : out Boolean);
      procedure Leave;
      procedure Set_Open (Done : out Boolean);
   private
      Busy   : Boolean := False;
      Opened : Boolean := False;
   end Gate;

   protected body Gate is
      procedure Enter (Ok : out Boolean) is
      begin
         Ok := not Busy and then Opened;
         if Ok then
            Busy := True;
         end if;
      end Enter;
      procedure Leave is
      begin
         Busy := False;
      end Leave;
      procedure Set_Open (Done : out Boolean) is
      begin
         Done := Opened;
         Opened := True;
      end Set_Open;
   end Gate;

   procedure Sink
     (Level : RCL.Logging.Severity; Logger, Message : String; Stamp_Ns : Long_Long_Integer)
   is
      use ROSIDL.Dynamic;
      Ok : Boolean;
   begin
      Gate.Enter (Ok);
      if not Ok then
         return;  --  Concurrent records are dropped from /rosout, not from the console.
      end if;
      declare
         Msg : constant ROSIDL.Dynamic.Message := Init (Support);
      begin
         Msg ("stamp") ("sec").As_Int32 := ROSIDL.Int32 (Stamp_Ns / 1_000_000_000);
         Msg ("stamp") ("nanosec").As_UInt32 := ROSIDL.UInt32 (Stamp_Ns mod 1_000_000_000);
         Msg ("level").As_UInt8 := ROSIDL.UInt8 (RCL.Logging.ROS_Level (Level));
         Msg ("name").Set_String (Logger);
         Msg ("msg").Set_String (Message);
         Msg ("file").Set_String ("");
         Msg ("function").Set_String ("");
         Msg ("line").As_UInt32 := 0;
         if not RCL.Contexts.Is_Shutdown then
            RCL.DDS.Write (Writer.all, ROSIDL.CDR.Encode (Msg));
         end if;
      end;
      Gate.Leave;
   exception
      when others =>
         Gate.Leave;
   end Sink;

   procedure Enable is
      Done : Boolean;
   begin
      Gate.Set_Open (Done);
      if Done then
         return;
      end if;
      Support := ROSIDL.Typesupport.Get_Message_Support ("rcl_interfaces", "Log");
      Writer := new RCL.DDS.Writer;
      RCL.DDS.Create (Writer.all, RCL.Process_Context.Participant.all, "rt/rosout",
                      ROSIDL.Typesupport.DDS_Type_Name (Support), RCL.QoS.Rosout,
                      User_Data => RCL.Graph.Endpoint_User_Data
                        (ROSIDL.Typesupport.DDS_Type_Name (Support)));
      RCL.Logging.Set_Sink (Sink'Access);
   exception
      when E : others =>
         Ada.Text_IO.Put_Line (Ada.Text_IO.Standard_Error,
                               "[WARN] /rosout disabled: " & Ada.Exceptions.Exception_Message (E));
   end Enable;

end RCL.Rosout;
