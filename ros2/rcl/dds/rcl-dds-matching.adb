with Ada.Containers.Vectors;
with Interfaces.C.Strings;
with System;

package body RCL.DDS.Matching is

   package C renames Interfaces.C;
   package CS renames Interfaces.C.Strings;
   use type C.int;

   ---------------------
   -- Instance_Handle --
   ---------------------

   function Instance_Handle (This : Writer) return Unsigned_64 is
      function Get (E : C.int; H : out Unsigned_64) return C.int
        with Import, Convention => C, External_Name => "dds_get_instance_handle";
      H : Unsigned_64;
   begin
      Check (Integer (Get (C.int (This.Handle), H)), "getting a writer instance handle");
      return H;
   end Instance_Handle;

   ----------------
   -- Writer_Key --
   ----------------

   type Guid_Bytes is array (1 .. 16) of Unsigned_8 with Convention => C;

   function Writer_Key (This : Reader; Writer_GUID : GUID; Key : String) return Key_Value is
      function Lookup
        (R : C.int; G : Guid_Bytes; K : C.char_array; V : out C.char_array;
         Cap : C.size_t) return C.int
        with Import, Convention => C, External_Name => "rclada_match_writer_key";
      Buffer : C.char_array (0 .. 255);
      Code   : constant C.int :=
        Lookup (C.int (This.Handle), Guid_Bytes (Writer_GUID), C.To_C (Key), Buffer,
                Buffer'Length);
   begin
      if Code = 1 then
         return (Lookup => Found, Value => To_Unbounded_String (C.To_Ada (Buffer)));
      elsif Code = 0 then
         return (Lookup => No_Key);
      elsif Code /= -1 then
         Check (Integer (Code + 1), "reading the matched writers of """
                & This.Topic_Name.all & """");
      end if;
      return (Lookup => Gone);
   end Writer_Key;

   ------------------------
   -- Has_Matched_Reader --
   ------------------------

   function Has_Matched_Reader (This : Writer; Key, Value : String) return Boolean is
      function Has (W : C.int; K, V : C.char_array) return C.int
        with Import, Convention => C, External_Name => "rclada_match_has_reader";
      Code : constant C.int := Has (C.int (This.Handle), C.To_C (Key), C.To_C (Value));
   begin
      Check (Integer (Code), "reading the matched readers of """ & This.Topic_Name.all & """");
      return Code = 1;
   end Has_Matched_Reader;

   -----------------------
   -- Service_Available --
   -----------------------

   function Service_Available
     (Request_Writer : Writer; Reply_Reader : Reader) return Boolean
   is
      function Available (W, R : C.int) return C.int
        with Import, Convention => C, External_Name => "rclada_match_service_available";
      Code : constant C.int :=
        Available (C.int (Request_Writer.Handle), C.int (Reply_Reader.Handle));
   begin
      Check (Integer (Code), "checking the service of """
             & Request_Writer.Topic_Name.all & """");
      return Code = 1;
   end Service_Available;

   -------------
   -- Builtin --
   -------------

   type C_Endpoint is record
      Topic_Name, Type_Name : CS.chars_ptr;
      Key, Participant_Key  : Guid_Bytes;
      Reliability, Durability, History, Depth : Integer_32;
      Deadline, Lifespan    : Integer_64;
      Liveliness            : Integer_32;
      Lease                 : Integer_64;
      User_Data             : CS.chars_ptr;
   end record
     with Convention => C;

   package Endpoint_Vectors is new Ada.Containers.Vectors (Positive, Endpoint);

   procedure Collect (Context : System.Address; E : access constant C_Endpoint)
     with Convention => C;

   procedure Collect (Context : System.Address; E : access constant C_Endpoint) is
      Into : Endpoint_Vectors.Vector with Import, Address => Context;
   begin
      Into.Append
        (Endpoint'(Topic_Name      => To_Unbounded_String (CS.Value (E.Topic_Name)),
          Type_Name       => To_Unbounded_String (CS.Value (E.Type_Name)),
          Key             => GUID (E.Key),
          Participant_Key => GUID (E.Participant_Key),
          Reliability     => Integer (E.Reliability),
          Durability      => Integer (E.Durability),
          History         => Integer (E.History),
          Depth           => Integer (E.Depth),
          Deadline        => Time_Ns (E.Deadline),
          Lifespan        => Time_Ns (E.Lifespan),
          Liveliness      => Integer (E.Liveliness),
          Lease           => Time_Ns (E.Lease),
          User_Data       => To_Unbounded_String (CS.Value (E.User_Data))));
   exception
      when others =>
         null;  --  Never propagate into C; the endpoint is skipped.
   end Collect;

   function Builtin (Owner : Participant'Class; Which : Builtin_Topic) return Endpoint_Array is
      type Callback is access procedure (Context : System.Address;
                                         E : access constant C_Endpoint)
        with Convention => C;
      function Read (P : C.int; W : C.int; CB : Callback; Context : System.Address)
                     return C.int
        with Import, Convention => C, External_Name => "rclada_match_builtin";
      Found : aliased Endpoint_Vectors.Vector;
      Code  : constant C.int :=
        Read (C.int (Owner.Handle), Builtin_Topic'Pos (Which), Collect'Access, Found'Address);
   begin
      Check (Integer (Code), "reading the DDS built-in topic of " & Which'Image);
      return Result : Endpoint_Array (1 .. Natural (Found.Length)) do
         for I in Result'Range loop
            Result (I) := Found (I);
         end loop;
      end return;
   end Builtin;

   ---------------------
   -- User_Data_Value --
   ---------------------

   function User_Data_Value (User_Data, Key : String) return String is
      Start : Positive := User_Data'First;
   begin
      while Start <= User_Data'Last loop
         declare
            Stop : Natural := Start;
         begin
            while Stop <= User_Data'Last and then User_Data (Stop) /= ';' loop
               Stop := Stop + 1;
            end loop;
            declare
               Item : constant String := User_Data (Start .. Stop - 1);
            begin
               for I in Item'Range loop
                  if Item (I) = '=' then
                     if Item (Item'First .. I - 1) = Key then
                        return Item (I + 1 .. Item'Last);
                     end if;
                     exit;
                  end if;
               end loop;
            end;
            Start := Stop + 1;
         end;
      end loop;
      return "";
   end User_Data_Value;

   --------------
   -- Id_Image --
   --------------

   function Id_Image (Prefix : GUID; Counter : Unsigned_32) return String is
      Hex : constant String := "0123456789abcdef";
      Bytes : GUID := Prefix;
      Result : Unbounded_String;

      function Hex_Image (B : Unsigned_8) return String is
        (if B < 16 then [Hex (Natural (B) + 1)]
         else [Hex (Natural (B / 16) + 1), Hex (Natural (B mod 16) + 1)]);
   begin
      for I in 0 .. 3 loop
         Bytes (13 + I) := Unsigned_8 (Shift_Right (Counter, 24 - 8 * I) and 16#FF#);
      end loop;
      for I in Bytes'Range loop
         if I = Bytes'First then
            Append (Result, (if Bytes (I) < 16 then " " else "") & Hex_Image (Bytes (I)));
         else
            Append (Result, "." & Hex_Image (Bytes (I)));
         end if;
      end loop;
      return To_String (Result);
   end Id_Image;

   ------------
   -- New_Id --
   ------------

   protected Counter is
      procedure Next (Value : out Unsigned_32);
   private
      Last : Unsigned_32 := 0;
   end Counter;

   protected body Counter is
      procedure Next (Value : out Unsigned_32) is
      begin
         Last := Last + 1;
         Value := Last;
      end Next;
   end Counter;

   function New_Id (Owner : Participant'Class) return String is
      N : Unsigned_32;
   begin
      Counter.Next (N);
      return Id_Image (Owner.Instance_GUID, N);
   end New_Id;

end RCL.DDS.Matching;
