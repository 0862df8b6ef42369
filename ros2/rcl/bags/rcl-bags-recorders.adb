with Ada.Strings.Fixed;
with RCL.DDS;
with RCL.Graph.Queries;
with RCL.Logging;
with RCL.QoS;
with ROSIDL;

package body RCL.Bags.Recorders is

   package Queries renames RCL.Graph.Queries;

   --  A subscription's handler: writes each sample to the bag.
   type Topic_Handler is new RCL.Nodes.Handler with record
      Shared : State_Access;
      Topic  : Topic_Index;
   end record;

   overriding procedure Deliver
     (This : in out Topic_Handler;
      Node : in out RCL.Nodes.Node'Class;
      Data : RCL.DDS.Byte_Array;
      Info : ROSIDL.Message_Info)
   is
      pragma Unreferenced (Node);
      S : State renames This.Shared.all;
   begin
      S.Guard.Seize;
      if S.Recording then
         S.Bag.Write (This.Topic, Time_Stamp (Info.Received_Timestamp), Data,
                      Publish_Time => Time_Stamp (Info.Source_Timestamp));
         S.Count := S.Count + 1;
      end if;
      S.Guard.Release;
   exception
      when others =>
         S.Guard.Release;
         raise;
   end Deliver;

   procedure Start
     (This           : in out Recorder;
      Output         : String;
      Topics         : Topic_List := All_Topics;
      Compression    : RCL.MCAP.Compression_Kind := RCL.MCAP.Zstd;
      Max_Bytes      : Interfaces.Unsigned_64 := 0;
      Max_Duration   : Duration := 0.0;
      Include_Hidden : Boolean := False;
      Mode           : Bag_Compression := No_Compression) is
   begin
      if This.Shared = null then
         This.Shared := new State;
      end if;
      This.Shared.Bag.Create (Output, Compression, Max_Bytes, Max_Duration, Background => True,
                              Mode => Mode);
      This.Shared.Recording := True;
      This.Shared.Count := 0;
      This.Wanted.Clear;
      for T of Topics loop
         This.Wanted.Append (if T'Length > 0 and then T (T'First) /= '/' then "/" & T else T);
      end loop;
      This.Recorded.Clear;
      This.Include_Hidden := Include_Hidden;
   end Start;

   function Is_Hidden (Name : String) return Boolean is
     (Ada.Strings.Fixed.Index (Name, "/_") /= 0);

   procedure Discover (This : in out Recorder; Node : in out RCL.Nodes.Node'Class) is
      use type RCL.QoS.Reliability_Policy;
      use type RCL.QoS.Durability_Policy;
   begin
      if This.Shared = null or else not This.Shared.Recording then
         return;
      end if;
      for T of Queries.Topic_Names_And_Types loop
         declare
            Name  : constant String := To_String (T.Name);
            Types : constant String := To_String (T.Types);
            Comma : constant Natural := Ada.Strings.Fixed.Index (Types, ",");
            Type_Name : constant String :=
              (if Comma = 0 then Types else Types (Types'First .. Comma - 1));
         begin
            if not This.Recorded.Contains (Name)
              and then (if This.Wanted.Is_Empty
                        then This.Include_Hidden or else not Is_Hidden (Name)
                        else This.Wanted.Contains (Name))
            then
               declare
                  Pubs  : constant Queries.Endpoint_Array := Queries.Publishers_Info (Name);
                  Offer : Profile_Array (1 .. Pubs'Length);
                  QoS   : RCL.QoS.Profile :=
                    (RCL.QoS.Default with delta History => RCL.QoS.Keep_All, Depth => 1000);
                  All_Local : Boolean := Pubs'Length > 0;
                  Index : Topic_Index;
                  DDS_Type : Unbounded_String;

                  procedure Add_Topic is
                  begin
                     Index := This.Shared.Bag.Add_Topic
                       (Name, Type_Name, Offered_QoS_Text (Offer));
                  end Add_Topic;
               begin
                  if Pubs'Length > 0 then
                     for I in Pubs'Range loop
                        Offer (I - Pubs'First + 1) := Pubs (I).QoS;
                        DDS_Type := Pubs (I).DDS_Type;
                        if Pubs (I).QoS.Reliability = RCL.QoS.Best_Effort then
                           QoS.Reliability := RCL.QoS.Best_Effort;
                        end if;
                        if Pubs (I).QoS.Durability /= RCL.QoS.Transient_Local then
                           All_Local := False;
                        end if;
                     end loop;
                     if All_Local then
                        QoS.Durability := RCL.QoS.Transient_Local;
                     end if;
                     ROSIDL.Mutexes.Run_Locked (This.Shared.Guard, Add_Topic'Access);
                     Node.Subscribe_Handler
                       (To_String (DDS_Type), Name,
                        new Topic_Handler'(Shared => This.Shared, Topic => Index), QoS);
                     This.Recorded.Append (Name);
                     RCL.Logging.Info ("Subscribed to topic '" & Name & "' (" & Type_Name & ")",
                                       Logger => Node.Logger_Name);
                  end if;
               end;
            end if;
         end;
      end loop;
   end Discover;

   function Topic_Count (This : Recorder) return Natural is (Natural (This.Recorded.Length));

   function Message_Count (This : Recorder) return Interfaces.Unsigned_64 is
     (if This.Shared = null then 0 else This.Shared.Count);

   procedure Stop (This : in out Recorder) is
      procedure Close is
      begin
         This.Shared.Recording := False;
         This.Shared.Bag.Close;
      end Close;
   begin
      if This.Shared /= null and then This.Shared.Recording then
         ROSIDL.Mutexes.Run_Locked (This.Shared.Guard, Close'Access);
      end if;
   end Stop;

   overriding procedure Finalize (This : in out Recorder) is
   begin
      Stop (This);
      --  Shared stays allocated: the node's handlers may still refer to it.
   exception
      when others => null;
   end Finalize;

end RCL.Bags.Recorders;
