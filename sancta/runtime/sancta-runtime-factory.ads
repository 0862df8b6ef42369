--  The factory: component types register themselves by name, with their
--  Descriptor and a creator, at the elaboration of their package:
--
--     package body Sancta.Standard_Components.Logger is
--        ...
--     begin
--        Sancta.Runtime.Factory.Register (Info, Create'Access);
--     end Sancta.Standard_Components.Logger;
--
--  There is no central list. Beware that a unit of a static library is only
--  elaborated (and so registered) when some unit of the program "with"s
--  it: programs "with Sancta.Standard_Components.All_Standard;" to get every standard
--  component, and add their own component packages the same way.
with Sancta.Runtime.Components;
with Sancta.Runtime.Local_Databases;

package Sancta.Runtime.Factory is

   type Creator is access function
     (Ctx : Components.Context) return Components.Component_Access;
   --  Allocates a component and calls its Initialize (This, Ctx).

   generic
      type Kind is new Components.Component with private;
   function Create_Component (Ctx : Components.Context) return Components.Component_Access;
   --  The usual Creator: a new Kind, initialized from Ctx.
   --     function Create is new Factory.Create_Component (Logger_Component);
   --     Factory.Register (Info, Create'Access);

   procedure Register (Info : Components.Descriptor; Create : not null Creator);
   --  Raises Program_Error when the name is already registered.

   function Is_Registered (Name : String) return Boolean;

   function Description (Name : String) return Components.Descriptor
     with Pre => Is_Registered (Name);

   function Create (Name : String; Ctx : Components.Context) return Components.Component_Access
     with Pre => Is_Registered (Name);

   function Names return Local_Databases.Key_Vectors.Vector;
   --  Every registered component name, sorted.

   function Closest (Name : String; Candidates : Local_Databases.Key_Vectors.Vector) return String;
   --  Up to three candidates nearest to Name by edit distance, case ignored
   --  (Sancta.Edit_Distances; within max (2, length / 3)), as "'a', 'b'";
   --  "" when none is near.

end Sancta.Runtime.Factory;
