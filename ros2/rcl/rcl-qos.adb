package body RCL.QoS is

   function Image (This : Profile) return String is
      function Hist return String is
        (case This.History is
            when Middleware_Default => "history default",
            when Keep_Last      => "KEEP_LAST" & This.Depth'Image,
            when Keep_All       => "KEEP_ALL");
      function Rel return String is
        (case This.Reliability is
            when Middleware_Default => "reliability default",
            when Best_Effort    => "BEST_EFFORT",
            when Reliable       => "RELIABLE");
      function Dur return String is
        (case This.Durability is
            when Middleware_Default  => "durability default",
            when Volatile        => "VOLATILE",
            when Transient_Local => "TRANSIENT_LOCAL");
      function Extra return String is
        ((if This.Deadline > 0.0 then ", deadline" & This.Deadline'Image else "")
         & (if This.Lifespan > 0.0 then ", lifespan" & This.Lifespan'Image else "")
         & (if This.Lease < Infinite then ", lease" & This.Lease'Image else "")
         & (if This.Destination_Order = By_Source_Timestamp then ", BY_SOURCE_TIMESTAMP"
            else ""));
   begin
      return Hist & ", " & Rel & ", " & Dur & Extra;
   end Image;

end RCL.QoS;
