--  sancta-view: the live mission view; see Sancta.Views.Main.
with Sancta.Views.Main;

procedure Sancta_View is
begin
   Sancta.Views.Main;
end Sancta_View;
