--  Node configurations: the XML format of the SANCTA paper (Listing 1.1)
--  with constants, groups and includes, loaded with positions and checked
--  against the factory's component descriptors before anything runs.
--
--     <any_name>
--       <include file="common.xml"/>              (relative to this file)
--       <constant name="$rate" value="10"/>        (--set rate=20 overrides)
--       <group name="sensors">                     (components shared by agents)
--         <component name="odometry"> ... </component>
--       </group>
--       <agent id="Ari" kind="robot">
--         <use group="sensors"/>
--         <component name="scan_matching" enabled="true" order="2" period="$rate">
--           <requires data="pose" as="odometric_pose" type="types.pose"/>
--           <provides data="pose" as="${id}_corrected_pose" type="types.pose"/>
--         </component>
--       </agent>
--     </any_name>
--
--  "$name" or "${name}" in any attribute of a component, provides or
--  requires is replaced by the constant's value; "$id" is the agent's id.
--  "as" defaults to "data"; "type", when given, must be a known value type
--  and agree with the component's declaration and with the other end of the
--  connection.
--
--  Load never raises on a wrong configuration: it collects Diagnostics
--  (errors and warnings, each with file:line:column) and a caller refuses
--  to start when Error_Count > 0.
with Ada.Containers.Indefinite_Vectors;
with Ada.Strings.Unbounded;
with Sancta.Runtime.Components;
with Sancta.Runtime.XML_Trees;

private with Ada.Characters.Handling;
private with Sancta.Runtime.Local_Databases;

package Sancta.Runtime.Configurations is

   use Ada.Strings.Unbounded;

   subtype Position is XML_Trees.Position;
   subtype String_Map is Components.String_Maps.Map;

   type Severity is (Warning, Error);

   type Diagnostic is record
      Level   : Severity;
      Where   : Position;
      Message : Unbounded_String;
   end record;

   function Image (D : Diagnostic) return String;
   --  "file:line:column: error: message".

   package Diagnostic_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Diagnostic);

   type Binding is record
      Direction : Components.Port_Direction;
      Data      : Unbounded_String;
      Key       : Unbounded_String;
      Type_Name : Unbounded_String;
      --  The effective type: the declared one, or the configured one for
      --  ports of any type.
      Optional  : Boolean := False;
      Any_Port  : Boolean := False;
      --  The component declares this port of any type.
      Where     : Position;
   end record;

   package Binding_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Binding);

   type Instance is record
      Component   : Unbounded_String;
      --  The registered component name ("logger").
      Name        : Unbounded_String;
      --  Unique in the agent: "logger#3" (the component's rank in the agent).
      Where       : Position;
      Enabled     : Boolean := True;
      Order       : Integer := 0;
      Rank        : Positive := 1;
      Options     : String_Map;
      Policy      : Components.Error_Policy := Components.Retry;
      Retry_After : Duration := 1.0;
      Bindings    : Binding_Vectors.Vector;
   end record;

   package Instance_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Instance);

   type Agent is record
      Id        : Unbounded_String;
      Kind      : Unbounded_String;
      Where     : Position;
      Instances : Instance_Vectors.Vector;
      --  Sorted by (Order, Rank): the start order.
   end record;

   package Agent_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, Agent);

   type Configuration is record
      File        : Unbounded_String;
      Name        : Unbounded_String;
      --  The root element's name.
      Constants   : String_Map;
      Agents      : Agent_Vectors.Vector;
      Diagnostics : Diagnostic_Vectors.Vector;
   end record;

   procedure Load
     (File      : String;
      Result    : out Configuration;
      Overrides : String_Map := Components.String_Maps.Empty_Map);
   --  Read and check File. Overrides: constant name (with or without "$")
   --  -> value, taking precedence over the file's constants.

   function Error_Count (This : Configuration) return Natural;
   function Warning_Count (This : Configuration) return Natural;

   function Find_Agent (This : Configuration; Id : String) return Natural;
   --  Index in This.Agents, 0 when absent.

   function Agent_Ids (This : Configuration) return String;
   --  "Ari, Ben" (for diagnostics).

   --  The children: Loading (reading the files) and Wiring (connecting each
   --  agent) are private; Rendering prints the wiring (table, Graphviz).

private

   procedure Report
     (Result : in out Configuration; Level : Severity; Where : Position; Message : String);
   --  Appends a diagnostic.

   function Is_Identifier_Char (C : Character) return Boolean is
     (Ada.Characters.Handling.Is_Alphanumeric (C) or else C = '_');
   --  A letter, a digit or '_'.

   function Trim (N : Integer) return String;
   --  N'Image without the leading space.

   function Suggest
     (Name : String; Candidates : Local_Databases.Key_Vectors.Vector) return String;
   --  " (did you mean X?)" with the candidate closest to Name, or "".

end Sancta.Runtime.Configurations;
