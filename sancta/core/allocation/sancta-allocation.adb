package body Sancta.Allocation is

   function Preset (Name : String; Found : out Boolean) return Criterion is
   begin
      Found := True;
      if Name = "minmax" then
         return Min_Max;
      elsif Name = "minsum" then
         return Min_Sum;
      elsif Name = "minave" then
         return Min_Ave;
      elsif Name = "minmix" then
         return Min_Mix;
      elsif Name = "mintim" then
         return Min_Tim;
      end if;
      Found := False;
      return Min_Sum;
   end Preset;

end Sancta.Allocation;
