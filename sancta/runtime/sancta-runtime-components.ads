--  Components: the black boxes of a node. A component type declares, in a
--  Descriptor, the options it accepts and its inputs and outputs (internal
--  "data" names with their value types), so a configuration is checked
--  before anything runs. The configuration binds each data name to an
--  external database key ("as").
--
--  Execution modes (a component may combine them):
--  * periodic: Run is called once at start; it sets Next to the time it
--    wants to be called again (Next comes in as the time it was due:
--    "Next := Next + Period" gives drift-free periods; Never stops the calls);
--  * event-driven: a Base_Component subscribes to its inputs (Subscribe)
--    and receives On_Input after each store of the bound key;
--  * asynchronous: the component starts its own task in Start and reports it
--    with Sancta.Runtime.Tasks.Watch so its termination is logged.
--  Run and On_Input of one component never overlap (a per-component
--  reentrant lock), so a component needs no protection of its own state
--  against itself.
--
--     type Doubler is new Base_Component with null record;
--     overriding procedure Start (This : in out Doubler) is
--     begin
--        This.Subscribe ("input");
--     end Start;
--     overriding procedure On_Input
--       (This : in out Doubler; Data : String; Item : Values.Value'Class) is
--     begin
--        This.Output ("output", Values.Real_Value'(Data => 2.0 * Values.Real_Value (Item).Data));
--     end On_Input;
with Ada.Containers.Indefinite_Ordered_Maps;
with Ada.Containers.Indefinite_Vectors;
with Ada.Exceptions;
with Ada.Real_Time;
with Ada.Strings.Unbounded;
with Ada.Task_Identification;
with Sancta.Logging;
with Sancta.Runtime.Clocks;
with Sancta.Runtime.Local_Databases;
with Sancta.Runtime.Values;

package Sancta.Runtime.Components is

   use Ada.Strings.Unbounded;

   --  Declarations --

   type Port_Direction is (Input, Output);

   type Port is record
      Data      : Unbounded_String;
      Direction : Port_Direction := Input;
      Type_Name : Unbounded_String;
      --  A registered value type name, or Values.Any_Type.
      Optional  : Boolean := False;
      --  A mandatory input must be bound ("requires") and provided by some
      --  component of the agent; mandatory outputs do not exist.
      Doc       : Unbounded_String;
   end record;

   function In_Port (Data, Type_Name : String; Optional : Boolean := False; Doc : String := "")
     return Port is
     ((Data => To_Unbounded_String (Data), Direction => Input,
       Type_Name => To_Unbounded_String (Type_Name), Optional => Optional,
       Doc => To_Unbounded_String (Doc)));
   function Out_Port (Data, Type_Name : String; Doc : String := "") return Port is
     ((Data => To_Unbounded_String (Data), Direction => Output,
       Type_Name => To_Unbounded_String (Type_Name), Optional => True,
       Doc => To_Unbounded_String (Doc)));

   type Option_Kind is (Text_Option, Integer_Option, Real_Option, Boolean_Option,
                        Duration_Option, Choice_Option);
   --  Duration_Option: seconds, 0 or Min_Duration .. Max_Duration (a
   --  "period" whose default is not 0 may not be 0: it would spin).
   --  Choice_Option: one of the words of Choices.

   Min_Duration : constant := 0.001;
   Max_Duration : constant := 31_536_000.0;

   type Option_Check is access function (Text : String) return String;
   --  "" when Text is acceptable, else what is wrong with it.

   type Option_Spec is record
      Name     : Unbounded_String;
      Kind     : Option_Kind := Text_Option;
      Default  : Unbounded_String;
      Required : Boolean := False;
      Choices  : Unbounded_String;
      --  Space-separated words, for Choice_Option.
      Doc      : Unbounded_String;
      Check    : Option_Check;
      --  A further check of the value (after the kind's), or null.
   end record;

   function Make_Option
     (Name     : String;
      Kind     : Option_Kind;
      Default  : String := "";
      Required : Boolean := False;
      Choices  : String := "";
      Doc      : String := "";
      Check    : Option_Check := null) return Option_Spec is
     ((Name => To_Unbounded_String (Name), Kind => Kind,
       Default => To_Unbounded_String (Default), Required => Required,
       Choices => To_Unbounded_String (Choices), Doc => To_Unbounded_String (Doc),
       Check => Check));

   function Check_Value (Item : Option_Spec; Text : String) return String;
   --  "" when Text is a valid value of the option, else what is wrong
   --  ("expected a real number, found 'abc'").

   package Port_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Port);
   package Option_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Option_Spec);

   package String_Maps is new Ada.Containers.Indefinite_Ordered_Maps (String, String);

   type Type_Refiner is access function
     (Options : String_Maps.Map; Data : String; Direction : Port_Direction) return String;
   --  The value type of a port declared of Values.Any_Type for an instance
   --  with these (valid) options, or "" to keep Any_Type. E.g. the output
   --  of a "value" component has the type its "type" option names.

   type Options_Check is access procedure
     (Options : String_Maps.Map; Option : out Unbounded_String; Problem : out Unbounded_String);
   --  Problem: "" when the options (every declared one, valid on its own)
   --  agree, else what is wrong, blaming Option.

   type Descriptor is record
      Name       : Unbounded_String;
      Doc        : Unbounded_String;
      Ports      : Port_Vectors.Vector;
      Options    : Option_Vectors.Vector;
      Any_Inputs : Boolean := False;
      --  Inputs of any data name and any type may be required as well
      --  (logger, merge, switch).
      Refine     : Type_Refiner;
      --  Null, or how the instance's options fix its ports' types.
      Check      : Options_Check;
      --  Null, or a check of the options together (after each one's own).
      Follows_Inputs : Boolean := False;
      --  Outputs of any type carry what the inputs of any type receive
      --  (copy, merge, switch): the configuration check gives them the
      --  type of what feeds those inputs, when it is one type.
   end record;

   function Is_Common_Option (Name : String) return Boolean is
     (Name in "name" | "enabled" | "order" | "on_error" | "retry_after");
   --  Attributes every <component> accepts: name, enabled (boolean), order
   --  (integer, start order, default 0), on_error (retry | stop, default
   --  retry), retry_after (seconds, default 1.0).

   --  Instances --

   type Error_Policy is (Retry, Stop);

   type Context is record
      Agent_Id      : Unbounded_String;
      Agent_Kind    : Unbounded_String;
      Instance_Name : Unbounded_String;
      --  "logger#2": the component name and its rank in the agent.
      Database      : Local_Databases.Database_Access;
      Clock         : Clocks.Clock_Access;
      Inputs        : String_Maps.Map;
      --  data -> external key, for each bound input.
      Outputs       : String_Maps.Map;
      Output_Types  : String_Maps.Map;
      --  data -> the type the configuration check settled for each bound
      --  output (absent or Values.Any_Type: not checked).
      Options       : String_Maps.Map;
      --  Every declared option with its (validated) value or default.
      Policy        : Error_Policy := Retry;
      Retry_After   : Ada.Real_Time.Time_Span := Ada.Real_Time.Seconds (1);
   end record;

   type Component is abstract tagged limited private;
   type Component_Access is access all Component'Class;

   Never : constant Clocks.Time := Ada.Real_Time.Time_Last;

   procedure Initialize (This : in out Component; Ctx : Context);
   --  Called by the factory's creators on a new component.

   procedure Start (This : in out Component) is null;
   --  After all components of the node exist, in start order (subscribe,
   --  start tasks here).

   procedure Run (This : in out Component; Next : in out Clocks.Time);
   --  Periodic entry point, called once at start; Next comes in as the time
   --  the call was due. The default sets Next := Never.

   procedure Stop (This : in out Component) is null;
   --  At shutdown, in reverse start order: stop tasks, flush files.

   --  Helpers for component writers --

   function Name (This : Component'Class) return String;
   function Agent_Id (This : Component'Class) return String;
   function Ctx (This : Component'Class) return Context;
   function Now (This : Component'Class) return Clocks.Time;
   function Database (This : Component'Class) return Local_Databases.Database_Access;

   function Option_Text (This : Component'Class; Name : String) return String;
   function Option_Real (This : Component'Class; Name : String) return Long_Float;
   function Option_Integer (This : Component'Class; Name : String) return Long_Long_Integer;
   function Option_Boolean (This : Component'Class; Name : String) return Boolean;
   function Option_Duration (This : Component'Class; Name : String)
     return Ada.Real_Time.Time_Span;
   --  The option's value (validated by the configuration check).

   function Has_Input (This : Component'Class; Data : String) return Boolean;
   function Has_Output (This : Component'Class; Data : String) return Boolean;
   function Input_Key (This : Component'Class; Data : String) return String;
   function Output_Key (This : Component'Class; Data : String) return String;

   function Input_Names (This : Component'Class) return String_Maps.Map;
   --  All bound inputs: data -> key.

   function Input (This : Component'Class; Data : String) return Values.Value'Class;
   --  The current value of a bound input (Unknown_Key when none yet).

   function Has_Value (This : Component'Class; Data : String) return Boolean;

   procedure Output (This : in out Component'Class; Data : String; Item : Values.Value'Class);
   --  Store Item under the key bound to output Data; nothing when the
   --  output is not bound (unused outputs may be omitted). Raises
   --  Type_Error when Item is not of the output's checked type (a bug of
   --  the component: the configuration promised that type to consumers).

   procedure Log (This : Component'Class; Severity : Logging.Level; Message : String);
   --  Logs under the section "<agent>/<instance>".

   --  Failures --

   function Failed (This : Component'Class) return Boolean;
   --  The component failed with policy Stop: it gets no more calls.

   procedure Report_Failure
     (This : in out Component'Class; Where : String; E : Ada.Exceptions.Exception_Occurrence);
   --  Log an exception of the component (with its name) and apply the
   --  policy (Stop marks it Failed). Call it with the component locked.

   function Failures (This : Component'Class) return Natural;

   function Started (This : Component'Class) return Boolean;
   procedure Set_Started (This : in out Component'Class);
   --  Whether Start completed (for the node and the scheduler).

   --  Serialisation of the entry points (used by the scheduler and the base
   --  listener; reentrant for the same task).

   procedure Lock (This : in out Component'Class);
   procedure Unlock (This : in out Component'Class);

   --  A component with a database listener --

   type Base_Component is abstract limited new Component and Local_Databases.Listener with private;

   procedure Subscribe (This : in out Base_Component; Data : String);
   --  Receive On_Input after every store of the key bound to input Data
   --  (nothing when the input is not bound).

   procedure On_Input
     (This : in out Base_Component; Data : String; Item : Values.Value'Class) is null;
   --  A subscribed input was stored.

   overriding procedure On_Key_Stored
     (This : in out Base_Component; Key : String; Item : Values.Value'Class);
   --  Translates the key to data names and calls On_Input under the
   --  component's lock; exceptions go to Report_Failure (Listener_Recursion
   --  propagates to the writer).

   overriding function Listener_Name (This : Base_Component) return String;

   overriding procedure Stop (This : in out Base_Component);
   --  Unsubscribes from everything. Overridings must call it.

private

   protected type Reentrant_Lock is
      entry Seize;
      procedure Release;
   private
      entry Wait;
      Owner : Ada.Task_Identification.Task_Id := Ada.Task_Identification.Null_Task_Id;
      Depth : Natural := 0;
   end Reentrant_Lock;

   type Component is abstract tagged limited record
      Info          : Context;
      Guard         : Reentrant_Lock;
      Failure_Count : Natural := 0;
      Is_Started    : Boolean := False with Atomic;
      Is_Failed     : Boolean := False with Atomic;
      --  Written under Guard, read without it.
   end record;

   type Base_Component is abstract limited new Component and Local_Databases.Listener with record
      Stopped : Boolean := False;
      --  Set by Stop (under the component's lock): a notification already
      --  under way when the component unsubscribed is then ignored.
   end record;

end Sancta.Runtime.Components;
