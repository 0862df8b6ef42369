--  Quality of service: the ROS 2 profiles and custom settings.
--
--  A Profile is plain data; RCL.DDS turns it into Cyclone QoS. The profiles
--  are those of rmw/qos_profiles.h (see docs/ros2-wire.md):
--  Example:
--     Pub : Publishers.Publisher :=
--       Node.Publish (Support, "/scan", QoS => RCL.QoS.Sensor_Data);
--     Custom : constant RCL.QoS.Profile :=
--       (RCL.QoS.Default with delta Depth => 1, Deadline => 0.1);
package RCL.QoS is

   type History_Policy is (Middleware_Default, Keep_Last, Keep_All);
   type Reliability_Policy is (Middleware_Default, Best_Effort, Reliable);
   type Durability_Policy is (Middleware_Default, Volatile, Transient_Local);
   type Liveliness_Policy is (Middleware_Default, Automatic, Manual_By_Topic);

   type Destination_Order_Policy is (By_Reception_Timestamp, By_Source_Timestamp);
   --  DDS DESTINATION_ORDER, which rmw does not expose (ROS 2 endpoints use
   --  By_Reception_Timestamp). A subscription By_Source_Timestamp keeps
   --  samples in their publishers' time order: one stamped earlier than the
   --  last sample kept (a publisher with a lagging clock, or a replay) is
   --  dropped and counted as a Message_Lost event (RCL.Events). Publishers
   --  must offer it too (DDS request/offer rule: an Incompatible_QoS event
   --  otherwise); ROS 2 publishers do not.

   Infinite : constant Duration := Duration'Last;
   Unset    : constant Duration := 0.0;
   --  Deadline and lifespan are only applied when set (> 0); a lease of
   --  Infinite (the default) means no lease.

   type Profile is record
      History     : History_Policy := Keep_Last;
      Depth       : Positive := 10;
      --  Used with Keep_Last only.
      Reliability : Reliability_Policy := Reliable;
      Durability  : Durability_Policy := Volatile;
      Deadline    : Duration := Unset;
      Lifespan    : Duration := Unset;
      Liveliness  : Liveliness_Policy := Automatic;
      Lease       : Duration := Infinite;
      Destination_Order : Destination_Order_Policy := By_Reception_Timestamp;
      --  A DDS policy ROS 2 does not expose (see Destination_Order_Policy).
   end record
     with Dynamic_Predicate =>
       Profile.Deadline >= 0.0 and then Profile.Lifespan >= 0.0
       and then Profile.Lease > 0.0;

   Default : constant Profile := (others => <>);
   --  KEEP_LAST 10, RELIABLE, VOLATILE.

   Sensor_Data : constant Profile :=
     (Depth => 5, Reliability => Best_Effort, others => <>);

   Services_Default : constant Profile := (others => <>);

   Parameters : constant Profile := (Depth => 1000, others => <>);

   Parameter_Events : constant Profile := (Depth => 1000, others => <>);

   Rosout : constant Profile :=
     (Depth => 1000, Durability => Transient_Local, Lifespan => 10.0,
      others => <>);

   Clock : constant Profile := (Depth => 1, Reliability => Best_Effort, others => <>);

   Action_Status : constant Profile := (Depth => 1, Durability => Transient_Local, others => <>);
   --  rcl_action's status topic (the last status array reaches late joiners).

   System_Default : constant Profile :=
     (History => Middleware_Default, Depth => 1, Reliability => Middleware_Default,
      Durability => Middleware_Default, Liveliness => Middleware_Default,
      others => <>);
   --  Whatever the middleware's defaults are.

   function Image (This : Profile) return String;
   --  A readable summary, e.g. "KEEP_LAST 10, RELIABLE, VOLATILE".

end RCL.QoS;
