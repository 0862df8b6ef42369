with Ada.Strings.Fixed;

package body Sancta.Runtime.Components is

   use type Ada.Task_Identification.Task_Id;

   function Is_Word_Of (Word, Words : String) return Boolean is
      Padded : constant String := " " & Words & " ";
   begin
      return Word'Length > 0 and then Ada.Strings.Fixed.Index (Padded, " " & Word & " ") > 0;
   end Is_Word_Of;

   function Check_Kind (Item : Option_Spec; Text : String) return String;

   function Check_Value (Item : Option_Spec; Text : String) return String is
      Problem : constant String := Check_Kind (Item, Text);
   begin
      if Problem = "" and then Item.Check /= null then
         return Item.Check (Text);
      end if;
      return Problem;
   end Check_Value;

   function Check_Kind (Item : Option_Spec; Text : String) return String is
      Found : constant String := ", found '" & Text & "'";
   begin
      case Item.Kind is
         when Text_Option =>
            return "";
         when Integer_Option =>
            declare
               Unused : constant Long_Long_Integer := Long_Long_Integer'Value (Text);
            begin
               return "";
            end;
         when Real_Option | Duration_Option =>
            declare
               X : constant Long_Float := Long_Float'Value (Text);
            begin
               if Item.Kind = Duration_Option and then X < 0.0 then
                  return "expected a duration in seconds (>= 0)" & Found;
               elsif Item.Kind = Duration_Option and then X'Valid
                 and then X > Max_Duration
               then
                  return "expected a duration of at most" & Max_Duration'Image
                    & " s (one year)" & Found;
               elsif Item.Kind = Duration_Option and then X > 0.0 and then X < Min_Duration
               then
                  return "a duration below the floor of 0.001 s (1 ms)" & Found;
               elsif Item.Kind = Duration_Option and then X = 0.0 and then Item.Name = "period"
                 and then To_String (Item.Default) not in "" | "0" | "0.0"
               then
                  return "a period of 0 would run without pause: at least 0.001 s" & Found;
               elsif X'Valid then
                  return "";
               else
                  return "expected a finite number" & Found;
               end if;
            end;
         when Boolean_Option =>
            return (if Text in "true" | "false" then ""
                    else "expected true or false" & Found);
         when Choice_Option =>
            return (if Is_Word_Of (Text, To_String (Item.Choices)) then ""
                    else "expected one of: " & To_String (Item.Choices) & Found);
      end case;
   exception
      when Constraint_Error =>
         return (case Item.Kind is
                    when Integer_Option => "expected an integer",
                    when Duration_Option => "expected a duration in seconds",
                    when others => "expected a real number") & Found;
   end Check_Kind;

   protected body Reentrant_Lock is
      entry Seize when True is
      begin
         if Owner = Ada.Task_Identification.Null_Task_Id then
            Owner := Seize'Caller;
            Depth := 1;
         elsif Owner = Seize'Caller then
            Depth := Depth + 1;
         else
            requeue Wait;
         end if;
      end Seize;

      entry Wait when Owner = Ada.Task_Identification.Null_Task_Id is
      begin
         Owner := Wait'Caller;
         Depth := 1;
      end Wait;

      procedure Release is
      begin
         if Depth > 0 then
            Depth := Depth - 1;
            if Depth = 0 then
               Owner := Ada.Task_Identification.Null_Task_Id;
            end if;
         end if;
      end Release;
   end Reentrant_Lock;

   procedure Initialize (This : in out Component; Ctx : Context) is
   begin
      This.Info := Ctx;
   end Initialize;

   procedure Run (This : in out Component; Next : in out Clocks.Time) is
      pragma Unreferenced (This);
   begin
      Next := Never;
   end Run;

   function Name (This : Component'Class) return String is (To_String (This.Info.Instance_Name));
   function Agent_Id (This : Component'Class) return String is (To_String (This.Info.Agent_Id));
   function Ctx (This : Component'Class) return Context is (This.Info);
   function Now (This : Component'Class) return Clocks.Time is (This.Info.Clock.Now);
   function Database (This : Component'Class) return Local_Databases.Database_Access is
     (This.Info.Database);

   function Option_Text (This : Component'Class; Name : String) return String is
      Position : constant String_Maps.Cursor := This.Info.Options.Find (Name);
   begin
      if not String_Maps.Has_Element (Position) then
         raise Program_Error with This.Name & ": undeclared option '" & Name & "'";
      end if;
      return String_Maps.Element (Position);
   end Option_Text;

   function Option_Real (This : Component'Class; Name : String) return Long_Float is
     (Long_Float'Value (This.Option_Text (Name)));

   function Option_Integer (This : Component'Class; Name : String) return Long_Long_Integer is
     (Long_Long_Integer'Value (This.Option_Text (Name)));

   function Option_Boolean (This : Component'Class; Name : String) return Boolean is
     (This.Option_Text (Name) = "true");

   function Option_Duration (This : Component'Class; Name : String)
     return Ada.Real_Time.Time_Span is
     (Ada.Real_Time.To_Time_Span (Duration (This.Option_Real (Name))));

   function Has_Input (This : Component'Class; Data : String) return Boolean is
     (This.Info.Inputs.Contains (Data));

   function Has_Output (This : Component'Class; Data : String) return Boolean is
     (This.Info.Outputs.Contains (Data));

   function Input_Key (This : Component'Class; Data : String) return String is
     (if This.Info.Inputs.Contains (Data) then This.Info.Inputs (Data)
      else raise Program_Error with This.Name & ": input '" & Data & "' is not bound");

   function Output_Key (This : Component'Class; Data : String) return String is
     (if This.Info.Outputs.Contains (Data) then This.Info.Outputs (Data)
      else raise Program_Error with This.Name & ": output '" & Data & "' is not bound");

   function Input_Names (This : Component'Class) return String_Maps.Map is (This.Info.Inputs);

   function Input (This : Component'Class; Data : String) return Values.Value'Class is
     (This.Info.Database.Get (This.Input_Key (Data)));

   function Has_Value (This : Component'Class; Data : String) return Boolean is
     (This.Has_Input (Data) and then This.Info.Database.Contains (This.Input_Key (Data)));

   procedure Output (This : in out Component'Class; Data : String; Item : Values.Value'Class) is
   begin
      if This.Has_Output (Data) then
         if This.Info.Output_Types.Contains (Data) then
            declare
               Expected : constant String := This.Info.Output_Types (Data);
            begin
               if Expected /= Values.Any_Type and then Item.Type_Name /= Expected then
                  raise Type_Error with "output '" & Data & "' of " & This.Name & " is of type "
                    & Expected & ", but a value of type " & Item.Type_Name & " was written";
               end if;
            end;
         end if;
         This.Info.Database.Put (This.Output_Key (Data), Item);
      end if;
   end Output;

   procedure Log (This : Component'Class; Severity : Logging.Level; Message : String) is
   begin
      Logging.Log (This.Agent_Id & "/" & This.Name, Severity, Message);
   end Log;

   function Failed (This : Component'Class) return Boolean is (This.Is_Failed);

   function Failures (This : Component'Class) return Natural is (This.Failure_Count);

   function Started (This : Component'Class) return Boolean is (This.Is_Started);

   procedure Set_Started (This : in out Component'Class) is
   begin
      This.Is_Started := True;
   end Set_Started;

   procedure Report_Failure
     (This : in out Component'Class; Where : String; E : Ada.Exceptions.Exception_Occurrence) is
   begin
      This.Failure_Count := This.Failure_Count + 1;
      if This.Info.Policy = Stop then
         This.Is_Failed := True;
      end if;
      This.Log (Logging.Error,
                "component " & This.Name & " of agent " & This.Agent_Id & " failed in " & Where
                & ": " & Ada.Exceptions.Exception_Name (E) & ": "
                & Ada.Exceptions.Exception_Message (E)
                & (if This.Info.Policy = Stop then "; stopped (on_error=stop)"
                   else "; will be retried (on_error=retry)"));
   end Report_Failure;

   procedure Lock (This : in out Component'Class) is
   begin
      This.Guard.Seize;
   end Lock;

   procedure Unlock (This : in out Component'Class) is
   begin
      This.Guard.Release;
   end Unlock;

   procedure Subscribe (This : in out Base_Component; Data : String) is
   begin
      if This.Has_Input (Data) then
         This.Info.Database.Listen
           (This.Input_Key (Data), Local_Databases.Listener_Access'(This'Unchecked_Access));
      end if;
   end Subscribe;

   overriding procedure On_Key_Stored
     (This : in out Base_Component; Key : String; Item : Values.Value'Class) is
   begin
      if This.Is_Failed then
         return;
      end if;
      This.Lock;
      if This.Stopped then
         This.Unlock;
         return;
      end if;
      begin
         for Position in This.Info.Inputs.Iterate loop
            if String_Maps.Element (Position) = Key then
               Base_Component'Class (This).On_Input (String_Maps.Key (Position), Item);
            end if;
         end loop;
      exception
         when Listener_Recursion =>
            This.Unlock;
            raise;
         when E : others =>
            Report_Failure (This, "On_Input (" & Key & ")", E);
      end;
      This.Unlock;
   end On_Key_Stored;

   overriding function Listener_Name (This : Base_Component) return String is
     (This.Agent_Id & "/" & This.Name);

   overriding procedure Stop (This : in out Base_Component) is
   begin
      This.Stopped := True;
      This.Info.Database.Unlisten_All (Local_Databases.Listener_Access'(This'Unchecked_Access));
   end Stop;

end Sancta.Runtime.Components;
