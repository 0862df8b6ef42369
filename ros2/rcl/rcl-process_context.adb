with Ada.Strings.Unbounded;
with Ada.Unchecked_Deallocation;
with RCL.Contexts;
with RCL.Security;

package body RCL.Process_Context is

   type Participant_Access is access RCL.DDS.Participant;
   procedure Free is new Ada.Unchecked_Deallocation (RCL.DDS.Participant, Participant_Access);

   Max_Wakers : constant := 64;
   type Waker_Array is array (1 .. Max_Wakers) of Waitset_Access;

   protected State is
      procedure Init
        (P         : out Participant_Access;
         Dom       : RCL.DDS.Domain_Id;
         Local     : Boolean;
         User_Data : String;
         Security  : RCL.Security.Credentials;
         Lease     : Duration);
      function Current return Participant_Access;
      function Initialized return Boolean;
      function Domain return RCL.DDS.Domain_Id;
      function Localhost_Only return Boolean;
      procedure Set_Shutdown (Wakers : out Waker_Array);
      function Down return Boolean;
      function Current_Wakers return Waker_Array;
      procedure Register (Hook : Waitset_Access; Key : out Positive);
      procedure Unregister (Key : Positive);
   private
      Part    : Participant_Access;
      Dom_Id  : RCL.DDS.Domain_Id := 0;
      Local   : Boolean := False;
      Is_Down : Boolean := False;
      Hooks   : Waker_Array := [others => null];
   end State;

   protected body State is
      procedure Init
        (P         : out Participant_Access;
         Dom       : RCL.DDS.Domain_Id;
         Local     : Boolean;
         User_Data : String;
         Security  : RCL.Security.Credentials;
         Lease     : Duration)
      is
         New_Part : Participant_Access := new RCL.DDS.Participant;
      begin
         if Part = null then
            begin
               RCL.DDS.Create (New_Part.all, Dom, Local, User_Data, Security, Lease);
            exception
               when others =>
                  Free (New_Part);
                  raise;
            end;
            Part := New_Part;
            Dom_Id := Dom;
            State.Local := Local;
         else
            Free (New_Part);
         end if;
         P := Part;
      end Init;

      function Current return Participant_Access is (Part);
      function Initialized return Boolean is (Part /= null);
      function Domain return RCL.DDS.Domain_Id is (Dom_Id);
      function Localhost_Only return Boolean is (Local);

      procedure Set_Shutdown (Wakers : out Waker_Array) is
      begin
         Is_Down := True;
         Wakers := Hooks;
      end Set_Shutdown;

      function Down return Boolean is (Is_Down);
      function Current_Wakers return Waker_Array is (Hooks);

      procedure Register (Hook : Waitset_Access; Key : out Positive) is
      begin
         for I in Hooks'Range loop
            if Hooks (I) = null then
               Hooks (I) := Hook;
               Key := I;
               return;
            end if;
         end loop;
         raise ROS_Exception with "more than" & Max_Wakers'Image & " executors spinning";
      end Register;

      procedure Unregister (Key : Positive) is
      begin
         if Key in Hooks'Range then
            Hooks (Key) := null;
         end if;
      end Unregister;
   end State;

   procedure Ensure
     (P     : out Participant_Access;
      Dom   : RCL.DDS.Domain_Id;
      Local : Boolean;
      Lease : Duration := RCL.DDS.Configured_Lease) is
   begin
      P := State.Current;
      if P = null then
         declare
            Settings : constant RCL.Security.Settings := RCL.Security.Current;
         begin
            State.Init (P, Dom, Local,
                        "enclave=" & Ada.Strings.Unbounded.To_String (Settings.Enclave) & ";",
                        RCL.Security.Resolve (Settings), Lease);
         end;
      end if;
   end Ensure;

   procedure Ensure_Participant
     (Domain         : RCL.DDS.Domain_Id;
      Localhost_Only : Boolean;
      Lease          : Duration := RCL.DDS.Configured_Lease)
   is
      P : Participant_Access;
   begin
      Ensure (P, Domain, Localhost_Only, Lease);
   end Ensure_Participant;

   function Participant return not null access RCL.DDS.Participant is
      P : Participant_Access;
   begin
      Ensure (P, RCL.Contexts.Domain, RCL.Contexts.Localhost_Only);
      return P;
   end Participant;

   function Is_Initialized return Boolean is (State.Initialized);
   function Domain return RCL.DDS.Domain_Id is (State.Domain);
   function Localhost_Only return Boolean is (State.Localhost_Only);

   procedure Wake (Wakers : Waker_Array) is
   begin
      for W of Wakers loop
         if W /= null then
            RCL.DDS.Wake (W.all);
         end if;
      end loop;
   end Wake;

   procedure Wake_Executors is
   begin
      Wake (State.Current_Wakers);
   end Wake_Executors;

   procedure Shutdown is
      Wakers : Waker_Array;
   begin
      State.Set_Shutdown (Wakers);
      Wake (Wakers);
   end Shutdown;

   function Is_Shutdown return Boolean is (State.Down);

   procedure Register_Waker (Set : not null Waitset_Access; Key : out Positive) is
   begin
      State.Register (Set, Key);
   end Register_Waker;

   procedure Unregister_Waker (Key : Positive) is
   begin
      State.Unregister (Key);
   end Unregister_Waker;

end RCL.Process_Context;
