with Ada.Numerics.Discrete_Random;
with Ada.Strings.Unbounded;
with ROSIDL.Interfaces;

package body RCL.Actions is

   use ROSIDL.Typesupport;
   use Ada.Strings.Unbounded;

   package Random_Bytes is new Ada.Numerics.Discrete_Random (ROSIDL.UInt8);

   protected Generator is
      procedure Next (Id : out Goal_Id);
   private
      G      : Random_Bytes.Generator;
      Seeded : Boolean := False;
   end Generator;

   protected body Generator is
      procedure Next (Id : out Goal_Id) is
         use type ROSIDL.UInt8;
      begin
         if not Seeded then
            Random_Bytes.Reset (G);  --  From the time of day.
            Seeded := True;
         end if;
         for B of Id loop
            B := Random_Bytes.Random (G);
         end loop;
         Id (7) := (Id (7) and 16#0F#) or 16#40#;  --  Version 4.
         Id (9) := (Id (9) and 16#3F#) or 16#80#;  --  RFC 4122 variant.
      end Next;
   end Generator;

   function New_Goal_Id return Goal_Id is
   begin
      return Id : Goal_Id do
         Generator.Next (Id);
      end return;
   end New_Goal_Id;

   function Image (Id : Goal_Id) return String is
      Hex    : constant String := "0123456789abcdef";
      Result : String (1 .. 32);
   begin
      for I in Id'Range loop
         Result (2 * I - 1) := Hex (Natural (Id (I)) / 16 + 1);
         Result (2 * I) := Hex (Natural (Id (I)) mod 16 + 1);
      end loop;
      return Result;
   end Image;

   function Status_Image (S : Goal_Status) return String is
     (case S is
         when Unknown   => "UNKNOWN",
         when Accepted  => "ACCEPTED",
         when Executing => "EXECUTING",
         when Canceling => "CANCELING",
         when Succeeded => "SUCCEEDED",
         when Canceled  => "CANCELED",
         when Aborted   => "ABORTED");

   function Get_Action_Support (Package_Name, Action_Name : String) return Action_Support is
     ((Definition => ROSIDL.Interfaces.Action (Package_Name, Action_Name)));

   function Full_Name (Support : Action_Support) return String is
     (To_String (Support.Definition.Package_Name) & "/action/"
      & To_String (Support.Definition.Name));

   function Goal_Support (Support : Action_Support) return Message_Support is
     (To_Support (Support.Definition.Goal));
   function Result_Support (Support : Action_Support) return Message_Support is
     (To_Support (Support.Definition.Result));
   function Feedback_Support (Support : Action_Support) return Message_Support is
     (To_Support (Support.Definition.Feedback));
   function Feedback_Message_Support (Support : Action_Support) return Message_Support is
     (To_Support (Support.Definition.Feedback_Message));
   function Send_Goal_Support (Support : Action_Support) return Service_Support is
     (To_Support (Support.Definition.Send_Goal));
   function Get_Result_Support (Support : Action_Support) return Service_Support is
     (To_Support (Support.Definition.Get_Result));

   function Cancel_Support return Service_Support is
     (Get_Service_Support ("action_msgs", "CancelGoal"));

   function Status_Support return Message_Support is
     (Get_Message_Support ("action_msgs", "GoalStatusArray"));

   function Goal_Message (Support : Action_Support) return ROSIDL.Dynamic.Message is
     (ROSIDL.Dynamic.Init (Goal_Support (Support)));
   function Result_Message (Support : Action_Support) return ROSIDL.Dynamic.Message is
     (ROSIDL.Dynamic.Init (Result_Support (Support)));
   function Feedback_Message (Support : Action_Support) return ROSIDL.Dynamic.Message is
     (ROSIDL.Dynamic.Init (Feedback_Support (Support)));

   procedure Put_Id (Ref : ROSIDL.Dynamic.Field_Ref; Id : Goal_Id) is
   begin
      Ref.Field_Reference ("uuid").Set_UInt8_Array (ROSIDL.Dynamic.UInt8_Array (Id));
   end Put_Id;

   function Get_Id (Ref : ROSIDL.Dynamic.Field_Ref) return Goal_Id is
     (Goal_Id (Ref.Field_Reference ("uuid").Get_UInt8_Array));

   procedure Put_Stamp (Ref : ROSIDL.Dynamic.Field_Ref; Nanoseconds : Long_Long_Integer) is
   begin
      Ref.Field_Reference ("sec").As_Int32.Element.all :=
        ROSIDL.Int32 (Nanoseconds / 1_000_000_000);
      Ref.Field_Reference ("nanosec").As_UInt32.Element.all :=
        ROSIDL.UInt32 (Nanoseconds mod 1_000_000_000);
   end Put_Stamp;

   function Get_Stamp (Ref : ROSIDL.Dynamic.Field_Ref) return Long_Long_Integer is
     (Long_Long_Integer (Ref.Field_Reference ("sec").As_Int32.Element.all) * 1_000_000_000
      + Long_Long_Integer (Ref.Field_Reference ("nanosec").As_UInt32.Element.all));

end RCL.Actions;
