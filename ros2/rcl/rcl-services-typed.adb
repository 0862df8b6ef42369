with Ada.Strings.Fixed;
with ROSIDL.CDR;
with ROSIDL.Dynamic;
with ROSIDL.Typesupport;

package body RCL.Services.Typed is

   function Support return ROSIDL.Typesupport.Service_Support is
      Full  : constant String := Handling.Full_Name;
      --  "pkg/srv/Name"
      First : constant Natural := Ada.Strings.Fixed.Index (Full, "/");
      Last  : constant Natural := Ada.Strings.Fixed.Index (Full, "/", Ada.Strings.Backward);
   begin
      return ROSIDL.Typesupport.Get_Service_Support
        (Full (Full'First .. First - 1), Full (Last + 1 .. Full'Last));
   end Support;

   function Call
     (Node    : RCL.Nodes.Node'Class;
      Name    : String;
      Req     : Request;
      Timeout : Duration := RCL.Clients.Forever) return Response
   is
      S       : constant ROSIDL.Typesupport.Service_Support := Support;
      Dynamic : constant ROSIDL.Dynamic.Message :=
        ROSIDL.CDR.Decode (ROSIDL.Typesupport.Request_Support (S),
                           Handling.Request_Handling.Encode (Req));
   begin
      return Handling.Response_Handling.Decode
        (ROSIDL.CDR.Encode (RCL.Clients.Call (Node, S, Name, Dynamic, Timeout)));
   end Call;

   package body Server is

      procedure Answer
        (Node     : in out RCL.Nodes.Node'Class;
         Request  : ROSIDL.Dynamic.Message;
         Response : in out ROSIDL.Dynamic.Message)
      is
         Req  : constant Typed.Request :=
           Handling.Request_Handling.Decode (ROSIDL.CDR.Encode (Request));
         Resp : Typed.Response;
      begin
         Callback (Node, Req, Resp);
         ROSIDL.CDR.Decode (Handling.Response_Handling.Encode (Resp), Response);
      end Answer;

      procedure Serve
        (Node : in out RCL.Nodes.Node'Class;
         Name : String;
         QoS  : RCL.QoS.Profile := RCL.QoS.Services_Default) is
      begin
         RCL.Services.Serve (Node, Support, Name, Answer'Access, QoS);
      end Serve;

   end Server;

end RCL.Services.Typed;
