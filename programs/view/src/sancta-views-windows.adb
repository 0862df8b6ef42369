with Ada.Containers;
with Cairo;
with Gdk.Event;
with Glib;
with Glib.Main;
with Gtk.Box;
with Gtk.Button;
with Gtk.Combo_Box;
with Gtk.Combo_Box_Text;
with Gtk.Dialog;
with Gtk.Drawing_Area;
with Gtk.File_Chooser;
with Gtk.File_Chooser_Dialog;
with Gtk.Label;
with Gtk.Main;
with Gtk.Toggle_Button;
with Gtk.Widget;
with Gtk.Window;
with Sancta.Geometry;
with Sancta.Views.Feeds;
with Sancta.Views.Scenes;

package body Sancta.Views.Windows is

   use Ada.Strings.Unbounded;
   use Glib;
   use Sancta.Geometry;
   use type Gdk.Event.Gdk_Scroll_Direction;
   use type Ada.Containers.Count_Type;
   use type Gdk.Event.Gdk_Event_Mask;

   --  The window's state (GTK calls everything from its own main loop) ----

   Settings  : Window_Config;
   Options   : Drawing.View_Options;
   Current   : Scenes.Scene;
   Last      : Drawing.Transform;
   Robots    : Scenes.Text_Vectors.Vector;
   --  The robots listed in the combo boxes.
   Dragging  : Boolean := False;
   Drag_From : Point;

   Window    : Gtk.Window.Gtk_Window;
   Area      : Gtk.Drawing_Area.Gtk_Drawing_Area;
   Follow    : Gtk.Combo_Box_Text.Gtk_Combo_Box_Text;
   Target    : Gtk.Combo_Box_Text.Gtk_Combo_Box_Text;

   function On_Draw
     (Self : access Gtk.Widget.Gtk_Widget_Record'Class; Cr : Cairo.Cairo_Context) return Boolean
   is
      Width  : constant Natural := Natural (Self.Get_Allocated_Width);
      Height : constant Natural := Natural (Self.Get_Allocated_Height);
   begin
      Drawing.Draw (Cr, Current, Width, Height, Options, Last);
      if Settings.Describe /= Null_Unbounded_String then
         declare
            X, Y : Gint;
            Ok   : Boolean;
         begin
            Self.Translate_Coordinates (Window, 0, 0, X, Y, Ok);
            Drawing.Write_Description
              (Current, Last, To_String (Settings.Describe), Real (X), Real (Y));
         end;
      end if;
      return True;
   end On_Draw;

   procedure Update_Robot_Lists is
   begin
      if Current.Robots.Length = Robots.Length then
         return;
      end if;
      for C in Current.Robots.Iterate loop
         declare
            Id : constant String := Scenes.Robot_Maps.Key (C);
         begin
            if not Robots.Contains (Id) then
               Robots.Append (Id);
               Follow.Append_Text (Id);
               Target.Append_Text (Id);
               if Target.Get_Active < 0 then
                  Target.Set_Active (0);
               end if;
            end if;
         end;
      end loop;
   end Update_Robot_Lists;

   function On_Tick return Boolean is
   begin
      if not Options.Paused then
         Current := Feeds.Scene_Store.Get;
         Update_Robot_Lists;
         Area.Queue_Draw;
      end if;
      if Feeds.Interrupted or else Scenes.Elapsed > Settings.Quit_After then
         Gtk.Main.Main_Quit;
         return False;
      end if;
      return True;
   end On_Tick;

   --  Mouse: drag to pan, wheel to zoom ------------------------------------

   function Centre_Now return Point is
     (Drawing.To_World
        (Last, Real (Natural'Max (1, Natural (Area.Get_Allocated_Width)
                                      - (if Natural (Area.Get_Allocated_Width)
                                               > 2 * Options.Panel_Width
                                         then Options.Panel_Width else 0))) / 2.0,
         Real (Area.Get_Allocated_Height) / 2.0));

   function On_Press
     (Self : access Gtk.Widget.Gtk_Widget_Record'Class; Event : Gdk.Event.Gdk_Event_Button)
      return Boolean
   is
      pragma Unreferenced (Self);
   begin
      Dragging := Event.Button = 1;
      Drag_From := (Real (Event.X), Real (Event.Y));
      return True;
   end On_Press;

   function On_Release
     (Self : access Gtk.Widget.Gtk_Widget_Record'Class; Event : Gdk.Event.Gdk_Event_Button)
      return Boolean
   is
      pragma Unreferenced (Self, Event);
   begin
      Dragging := False;
      return True;
   end On_Release;

   function On_Motion
     (Self : access Gtk.Widget.Gtk_Widget_Record'Class; Event : Gdk.Event.Gdk_Event_Motion)
      return Boolean
   is
      pragma Unreferenced (Self);
      Here : constant Point := (Real (Event.X), Real (Event.Y));
   begin
      if Dragging then
         Options.Centre := Centre_Now
           + (1.0 / Last.Scale) * Point'(Drag_From.X - Here.X, Here.Y - Drag_From.Y);
         Options.Has_Centre := True;
         Options.Follow := Null_Unbounded_String;
         Follow.Set_Active (0);
         Drag_From := Here;
         Area.Queue_Draw;
      end if;
      return True;
   end On_Motion;

   procedure Zoom (Factor : Real) is
   begin
      Options.Centre := Centre_Now;
      Options.Has_Centre := True;
      Options.Zoom := Real'Max (0.2, Real'Min (40.0, Options.Zoom * Factor));
      Area.Queue_Draw;
   end Zoom;

   function On_Scroll
     (Self : access Gtk.Widget.Gtk_Widget_Record'Class; Event : Gdk.Event.Gdk_Event_Scroll)
      return Boolean
   is
      pragma Unreferenced (Self);
   begin
      if Event.Direction = Gdk.Event.Scroll_Up then
         Zoom (1.25);
      elsif Event.Direction = Gdk.Event.Scroll_Down then
         Zoom (0.8);
      end if;
      return True;
   end On_Scroll;

   --  Tool bar ---------------------------------------------------------------

   procedure On_Zoom_In (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
   begin
      Zoom (1.25);
   end On_Zoom_In;

   procedure On_Zoom_Out (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
   begin
      Zoom (0.8);
   end On_Zoom_Out;

   procedure On_Fit (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
   begin
      Options.Zoom := 1.0;
      Options.Has_Centre := False;
      Options.Follow := Null_Unbounded_String;
      Follow.Set_Active (0);
      Area.Queue_Draw;
   end On_Fit;

   procedure On_Follow (Self : access Gtk.Combo_Box.Gtk_Combo_Box_Record'Class) is
      pragma Unreferenced (Self);
   begin
      Options.Follow :=
        (if Follow.Get_Active <= 0 then Null_Unbounded_String
         else To_Unbounded_String (Follow.Get_Active_Text));
      Area.Queue_Draw;
   end On_Follow;

   procedure On_Scans (Self : access Gtk.Toggle_Button.Gtk_Toggle_Button_Record'Class) is
   begin
      Options.Show_Scans := Self.Get_Active;
      if Options.Show_Scans then
         Feeds.Show_Scans;
      end if;
   end On_Scans;

   procedure On_Trails (Self : access Gtk.Toggle_Button.Gtk_Toggle_Button_Record'Class) is
   begin
      Options.Show_Trails := Self.Get_Active;
      Area.Queue_Draw;
   end On_Trails;

   procedure On_Pause (Self : access Gtk.Toggle_Button.Gtk_Toggle_Button_Record'Class) is
   begin
      Options.Paused := Self.Get_Active;
      Area.Queue_Draw;
   end On_Pause;

   procedure On_Kill (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
   begin
      if Target.Get_Active >= 0 then
         Feeds.Request_Control ("kill", Target.Get_Active_Text);
      end if;
   end On_Kill;

   procedure On_Revive (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
   begin
      if Target.Get_Active >= 0 then
         Feeds.Request_Control ("revive", Target.Get_Active_Text);
      end if;
   end On_Revive;

   procedure On_Load (Self : access Gtk.Button.Gtk_Button_Record'Class) is
      pragma Unreferenced (Self);
      use type Gtk.Dialog.Gtk_Response_Type;
      Chooser : Gtk.File_Chooser_Dialog.Gtk_File_Chooser_Dialog;
      Ignored : Gtk.Widget.Gtk_Widget;
   begin
      Gtk.File_Chooser_Dialog.Gtk_New
        (Chooser, "Load a mission (published to the team)", Window,
         Gtk.File_Chooser.Action_Open);
      Ignored := Chooser.Add_Button ("Cancel", Gtk.Dialog.Gtk_Response_Cancel);
      Ignored := Chooser.Add_Button ("Publish", Gtk.Dialog.Gtk_Response_Accept);
      if Chooser.Run = Gtk.Dialog.Gtk_Response_Accept then
         Feeds.Request_Mission (Chooser.Get_Filename);
      end if;
      Chooser.Destroy;
   end On_Load;

   procedure On_Close (Self : access Gtk.Widget.Gtk_Widget_Record'Class) is
      pragma Unreferenced (Self);
   begin
      Gtk.Main.Main_Quit;
   end On_Close;

   procedure Run (Config : Window_Config) is
      Column  : Gtk.Box.Gtk_Vbox;
      Bar     : Gtk.Box.Gtk_Hbox;
      Source  : Glib.Main.G_Source_Id with Unreferenced;

      procedure Add_Button
        (Title : String; Call : Gtk.Button.Cb_Gtk_Button_Void)
      is
         B : Gtk.Button.Gtk_Button;
      begin
         Gtk.Button.Gtk_New (B, Title);
         B.On_Clicked (Call);
         Bar.Pack_Start (B, Expand => False, Fill => False, Padding => 1);
      end Add_Button;

      procedure Add_Toggle
        (Title : String; On : Boolean; Call : Gtk.Toggle_Button.Cb_Gtk_Toggle_Button_Void)
      is
         B : Gtk.Toggle_Button.Gtk_Toggle_Button;
      begin
         Gtk.Toggle_Button.Gtk_New (B, Title);
         B.Set_Active (On);
         B.On_Toggled (Call);
         Bar.Pack_Start (B, Expand => False, Fill => False, Padding => 1);
      end Add_Toggle;

      procedure Add_Label (Title : String) is
         L : Gtk.Label.Gtk_Label;
      begin
         Gtk.Label.Gtk_New (L, Title);
         Bar.Pack_Start (L, Expand => False, Fill => False, Padding => 4);
      end Add_Label;
   begin
      Settings := Config;
      Options := Config.Options;
      if not Gtk.Main.Init_Check then
         raise Program_Error with "no display (set DISPLAY, or use --snapshot FILE.png)";
      end if;
      Gtk.Window.Gtk_New (Window);
      Window.Set_Title ("SANCTA live mission view");
      Window.Set_Default_Size (Gint (Config.Width), Gint (Config.Height));
      Window.On_Destroy (On_Close'Access);
      Gtk.Box.Gtk_New_Vbox (Column);
      Gtk.Box.Gtk_New_Hbox (Bar, Spacing => 2);
      Add_Button ("Zoom +", On_Zoom_In'Access);
      Add_Button ("Zoom -", On_Zoom_Out'Access);
      Add_Button ("Fit", On_Fit'Access);
      Add_Label ("follow");
      Gtk.Combo_Box_Text.Gtk_New (Follow);
      Follow.Append_Text ("none");
      Follow.Set_Active (0);
      Follow.On_Changed (On_Follow'Access);
      Bar.Pack_Start (Follow, Expand => False, Fill => False);
      Add_Toggle ("Scans", Options.Show_Scans, On_Scans'Access);
      Add_Toggle ("Trails", Options.Show_Trails, On_Trails'Access);
      Add_Toggle ("Pause", False, On_Pause'Access);
      Add_Button ("Load mission...", On_Load'Access);
      Add_Label ("  robot");
      Gtk.Combo_Box_Text.Gtk_New (Target);
      Bar.Pack_Start (Target, Expand => False, Fill => False);
      Add_Button ("Kill", On_Kill'Access);
      Add_Button ("Revive", On_Revive'Access);
      Column.Pack_Start (Bar, Expand => False, Fill => False);
      Gtk.Drawing_Area.Gtk_New (Area);
      Area.Add_Events (Gdk.Event.Button_Press_Mask or Gdk.Event.Button_Release_Mask
                       or Gdk.Event.Pointer_Motion_Mask or Gdk.Event.Scroll_Mask);
      Area.On_Draw (On_Draw'Access);
      Area.On_Button_Press_Event (On_Press'Access);
      Area.On_Button_Release_Event (On_Release'Access);
      Area.On_Motion_Notify_Event (On_Motion'Access);
      Area.On_Scroll_Event (On_Scroll'Access);
      Column.Pack_Start (Area, Expand => True, Fill => True);
      Window.Add (Column);
      Window.Show_All;
      if Options.Show_Scans then
         Feeds.Show_Scans;
      end if;
      Source := Glib.Main.Timeout_Add (100, On_Tick'Access);
      Gtk.Main.Main;
   end Run;

end Sancta.Views.Windows;
