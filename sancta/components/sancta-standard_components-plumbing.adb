with Ada.Strings.Unbounded;

package body Sancta.Standard_Components.Plumbing is

   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;

   --  copy and merge --

   type Forwarder is new Base_Component with null record;

   overriding procedure Start (This : in out Forwarder);
   overriding procedure On_Input
     (This : in out Forwarder; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Forwarder) is
   begin
      for Position in This.Input_Names.Iterate loop
         This.Subscribe (String_Maps.Key (Position));
      end loop;
   end Start;

   overriding procedure On_Input
     (This : in out Forwarder; Data : String; Item : Values.Value'Class)
   is
      pragma Unreferenced (Data);
   begin
      This.Output ("output", Item);
   end On_Input;

   function Create_Forwarder is new Factory.Create_Component (Forwarder);

   --  switch --

   type Switch is new Base_Component with record
      Selected : Unbounded_String;
   end record;

   overriding procedure Start (This : in out Switch);
   overriding procedure On_Input
     (This : in out Switch; Data : String; Item : Values.Value'Class);

   overriding procedure Start (This : in out Switch) is
   begin
      This.Selected := To_Unbounded_String (This.Option_Text ("initial"));
      for Position in This.Input_Names.Iterate loop
         This.Subscribe (String_Maps.Key (Position));
      end loop;
   end Start;

   overriding procedure On_Input
     (This : in out Switch; Data : String; Item : Values.Value'Class) is
   begin
      if Data = "select" then
         This.Selected := To_Unbounded_String (Item.Image);
         declare
            Chosen : constant String := To_String (This.Selected);
         begin
            if Chosen /= "select" and then This.Has_Value (Chosen) then
               This.Output ("output", This.Input (Chosen));
            elsif not This.Has_Input (Chosen) then
               raise Constraint_Error with "switch: no input named '" & Chosen & "'";
            end if;
         end;
      elsif Data = To_String (This.Selected) then
         This.Output ("output", Item);
      end if;
   end On_Input;

   function Create_Switch is new Factory.Create_Component (Switch);

begin
   Factory.Register
     ((Name       => To_Unbounded_String ("copy"),
       Doc        => To_Unbounded_String ("copies its input to its output"),
       Ports      => Port_Vectors.Empty_Vector
                       & In_Port ("input", Values.Any_Type)
                       & Out_Port ("output", Values.Any_Type),
       Options    => Option_Vectors.Empty_Vector,
       Any_Inputs => False,
       Refine     => null,
       Follows_Inputs => True,
       others     => <>),
      Create_Forwarder'Access);
   Factory.Register
     ((Name       => To_Unbounded_String ("merge"),
       Doc        => To_Unbounded_String ("forwards the last stored of its inputs"),
       Ports      => Port_Vectors.Empty_Vector & Out_Port ("output", Values.Any_Type),
       Options    => Option_Vectors.Empty_Vector,
       Any_Inputs => True,
       Refine     => null,
       Follows_Inputs => True,
       others     => <>),
      Create_Forwarder'Access);
   Factory.Register
     ((Name       => To_Unbounded_String ("switch"),
       Doc        => To_Unbounded_String ("forwards the input named by 'select'"),
       Ports      => Port_Vectors.Empty_Vector
                       & In_Port ("select", "types.string", Optional => True)
                       & Out_Port ("output", Values.Any_Type),
       Options    => Option_Vectors.Empty_Vector & Make_Option ("initial", Text_Option, ""),
       Any_Inputs => True,
       Refine     => null,
       Follows_Inputs => True,
       others     => <>),
      Create_Switch'Access);
end Sancta.Standard_Components.Plumbing;
