with Ada.Containers.Indefinite_Hashed_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Exceptions;
with Ada.Strings.Hash;
with Ada.Task_Termination;
with Sancta.Logging;

package body Sancta.Runtime.Tasks is

   use Ada.Task_Termination;

   package Name_Maps is new Ada.Containers.Indefinite_Hashed_Maps
     (String, String, Ada.Strings.Hash, "=");

   type Event (Length : Natural) is record
      Error : Boolean;
      Text  : String (1 .. Length);
   end record;

   package Event_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Event);

   protected Monitor is
      procedure Add (Id : Ada.Task_Identification.Task_Id; Name : String);
      procedure Ended
        (Cause : Cause_Of_Termination;
         T     : Ada.Task_Identification.Task_Id;
         X     : Ada.Exceptions.Exception_Occurrence);
      procedure Take (Events : out Event_Vectors.Vector);
      function Count return Natural;
   private
      Names    : Name_Maps.Map;
      Pending  : Event_Vectors.Vector;
      Abnormal_Count : Natural := 0;
   end Monitor;

   protected body Monitor is
      procedure Add (Id : Ada.Task_Identification.Task_Id; Name : String) is
      begin
         Names.Include (Ada.Task_Identification.Image (Id), Name);
      end Add;

      procedure Ended
        (Cause : Cause_Of_Termination;
         T     : Ada.Task_Identification.Task_Id;
         X     : Ada.Exceptions.Exception_Occurrence)
      is
         Id   : constant String := Ada.Task_Identification.Image (T);
         Name : constant String := (if Names.Contains (Id) then Names (Id) else Id);
         Text : constant String :=
           (case Cause is
              when Normal => "task of " & Name & " ended",
              when Abnormal => "task of " & Name & " was aborted",
              when Unhandled_Exception =>
                 "task of " & Name & " died of an unhandled exception: "
                 & Ada.Exceptions.Exception_Name (X) & ": "
                 & Ada.Exceptions.Exception_Message (X));
      begin
         if Cause /= Normal then
            Abnormal_Count := Abnormal_Count + 1;
         end if;
         Pending.Append (Event'(Text'Length, Cause /= Normal, Text));
         Names.Exclude (Id);
      end Ended;

      procedure Take (Events : out Event_Vectors.Vector) is
      begin
         Events := Pending;
         Pending.Clear;
      end Take;

      function Count return Natural is (Abnormal_Count);
   end Monitor;

   procedure Watch (Id : Ada.Task_Identification.Task_Id; Name : String) is
   begin
      Monitor.Add (Id, Name);
      Set_Specific_Handler (Id, Monitor.Ended'Access);
   end Watch;

   procedure Report_Ended is
      Events : Event_Vectors.Vector;
   begin
      Monitor.Take (Events);
      for E of Events loop
         Logging.Log ("tasks", (if E.Error then Logging.Error else Logging.Debug), E.Text);
      end loop;
   end Report_Ended;

   function Abnormal_Ends return Natural is (Monitor.Count);

   procedure Await_Termination (Id : Ada.Task_Identification.Task_Id) is
   begin
      while not Ada.Task_Identification.Is_Terminated (Id) loop
         delay 0.01;
      end loop;
   end Await_Termination;

end Sancta.Runtime.Tasks;
