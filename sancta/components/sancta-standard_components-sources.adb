with Ada.Real_Time;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Sancta.Geometry;
with Sancta.Runtime.Clocks;

package body Sancta.Standard_Components.Sources is

   use Ada.Strings.Unbounded;
   use Sancta.Runtime;
   use Sancta.Runtime.Components;
   use type Port_Vectors.Vector;
   use type Option_Vectors.Vector;
   use type Ada.Real_Time.Time;
   use type Ada.Real_Time.Time_Span;

   function Parse (Type_Name, Text : String) return Values.Value'Class is
      use Ada.Strings.Fixed;
   begin
      if Type_Name = "types.real" then
         return Values.Real_Value'(Data => Long_Float'Value (Text));
      elsif Type_Name = "types.integer" then
         return Values.Integer_Value'(Data => Long_Long_Integer'Value (Text));
      elsif Type_Name = "types.boolean" then
         if Text not in "true" | "false" then
            raise Constraint_Error with "expected true or false, found '" & Text & "'";
         end if;
         return Values.Boolean_Value'(Data => Text = "true");
      elsif Type_Name = "types.string" then
         return Values.To_Value (Text);
      else
         declare
            T      : constant String := Trim (Text, Ada.Strings.Both);
            First  : constant Natural := Index (T, " ");
            Second : constant Natural :=
              (if First = 0 then 0 else Index (T (First + 1 .. T'Last), " "));
         begin
            if First = 0 or else Second = 0 then
               raise Constraint_Error with "expected a pose ""x y yaw"", found '" & Text & "'";
            end if;
            return Values.Pose_Value'
              (Data => (X   => Geometry.Real'Value (T (T'First .. First - 1)),
                        Y   => Geometry.Real'Value (T (First + 1 .. Second - 1)),
                        Yaw => Geometry.Real'Value (T (Second + 1 .. T'Last))));
         end;
      end if;
   end Parse;

   function Output_Type
     (Options : String_Maps.Map; Data : String; Direction : Port_Direction) return String is
     (if Data = "output" and then Direction = Output then Options ("type") else "");

   procedure Check_Value
     (Options : String_Maps.Map; Option : out Unbounded_String; Problem : out Unbounded_String) is
   begin
      Option := To_Unbounded_String ("value");
      Problem := Null_Unbounded_String;
      declare
         Unused : constant Values.Value'Class := Parse (Options ("type"), Options ("value"));
      begin
         null;
      end;
   exception
      when Constraint_Error =>
         Problem := To_Unbounded_String
           ("'" & Options ("value") & "' is no " & Options ("type")
            & (if Options ("type") = "types.pose" then " (expected ""x y yaw"")" else ""));
   end Check_Value;

   type Source is new Component with record
      Item_Type : Unbounded_String;
      Text      : Unbounded_String;
      Period    : Ada.Real_Time.Time_Span;
   end record;

   overriding procedure Start (This : in out Source);
   overriding procedure Run (This : in out Source; Next : in out Clocks.Time);

   overriding procedure Start (This : in out Source) is
   begin
      This.Item_Type := To_Unbounded_String (This.Option_Text ("type"));
      This.Text := To_Unbounded_String (This.Option_Text ("value"));
      This.Period := This.Option_Duration ("period");
      declare
         Unused : constant Values.Value'Class :=
           Parse (To_String (This.Item_Type), To_String (This.Text));
      begin
         null;
      end;
   end Start;

   overriding procedure Run (This : in out Source; Next : in out Clocks.Time) is
   begin
      This.Output ("output", Parse (To_String (This.Item_Type), To_String (This.Text)));
      Next := (if This.Period > Ada.Real_Time.Time_Span_Zero then Next + This.Period
               else Never);
   end Run;

   function Create is new Factory.Create_Component (Source);

begin
   Factory.Register
     ((Name       => To_Unbounded_String ("value"),
       Doc        => To_Unbounded_String ("stores a configured value, once or periodically"),
       Ports      => Port_Vectors.Empty_Vector & Out_Port ("output", Values.Any_Type),
       Options    => Option_Vectors.Empty_Vector
                       & Make_Option ("type", Choice_Option, "types.real",
                                      Choices => "types.real types.integer types.boolean "
                                                 & "types.string types.pose")
                       & Make_Option ("value", Text_Option, Required => True)
                       & Make_Option ("period", Duration_Option, "0"),
       Any_Inputs => False,
       Refine     => Output_Type'Access,
       Check      => Check_Value'Access,
       others     => <>),
      Create'Access);
end Sancta.Standard_Components.Sources;
