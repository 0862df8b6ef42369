--  Drives the Ada CDR codec for the interoperability tests:
--     cdr_tool list                 the sample names
--     cdr_tool encode NAME [be]     the sample's encoding, as hex
--     cdr_tool image NAME           the sample as ros2 topic echo prints it
--     cdr_tool decode NAME HEX      decodes HEX as the sample's type and
--                                   prints its image (exit 2 and the
--                                   Decode_Error text on malformed input)
--     cdr_tool types                every message type: "T dds_name" then
--                                   "F name kind collection size bound
--                                   nested_dds_name|-" per field
--     cdr_tool random SEED [user]   a random message of every type (printable
--                                   ASCII strings): "dds_name hex" lines
--                                   ("user": also the types of
--                                   tests/data/user_interfaces)
--     cdr_tool reencode [user]      reads "dds_name hex" lines, decodes each
--                                   and prints "dds_name hex" of its
--                                   little-endian re-encoding (or
--                                   "dds_name ERROR text"; "dds_name
--                                   INTERNAL exception: text" when the
--                                   decoder raised anything else)
--     cdr_tool reencode typed       the same through the generated codecs
--                                   (every type of the registries
--                                   ROSIDL.Static.Bundled_Types and
--                                   Test_Types; "dds_name NONE" for a type
--                                   with no generated codec)
with Ada.Command_Line;
with Ada.Exceptions;
with Ada.Streams;
with Ada.Strings.Fixed;
with Ada.Strings.Unbounded;
with Ada.Text_IO;
with Ada.Unchecked_Deallocation;
with ROSIDL.CDR;
with ROSIDL.CDR_Samples;
with ROSIDL.Definitions;
with ROSIDL.Dynamic;
with ROSIDL.Static.Bundled_Types;
with ROSIDL.Static.Registries;
with ROSIDL.Static.Test_Types;
with ROSIDL.Typesupport;

procedure CDR_Tool is
   use Ada.Command_Line;
   use Ada.Text_IO;
   use ROSIDL.CDR;
   package Samples renames ROSIDL.CDR_Samples;

   Bad_Argument : exception;
   --  Its message says which argument is wrong and why.

   procedure Put_Image (Text : String) is
   begin
      --  Text ends with LF: written so that Text_IO adds no terminator.
      Put (Text (Text'First .. Text'Last - 1));
      New_Line;
   end Put_Image;

   function Trim (S : String) return String is
     (if S'Length > 0 and then S (S'First) = ' ' then S (S'First + 1 .. S'Last) else S);

   procedure Put_Types is
      use ROSIDL.Definitions;
   begin
      for Support of Samples.All_Types loop
         Put_Line ("T " & ROSIDL.Typesupport.DDS_Type_Name (Support));
         for F of ROSIDL.Typesupport.Definition (Support).Fields loop
            declare
               T : constant Field_Type := F.Of_Type;
            begin
               Put_Line ("F " & Ada.Strings.Unbounded.To_String (F.Name) & " "
                         & (case T.Kind is
                               when Primitive_Kind => Type_Name (T.Kind),
                               when String_Kind => "string",
                               when WString_Kind => "wstring",
                               when Message_Kind => "message")
                         & " " & T.Collection'Image & " " & Trim (T.Size'Image) & " "
                         & Trim (T.String_Bound'Image) & " "
                         & (if T.Kind = Message_Kind then DDS_Type_Name (T.Nested.all)
                            else "-"));
            end;
         end loop;
      end loop;
   end Put_Types;

   procedure Put_Random (Seed_Text : String) is
      Seed : ROSIDL.UInt64;
   begin
      begin
         Seed := ROSIDL.UInt64'Value (Seed_Text);
      exception
         when Constraint_Error =>
            raise Bad_Argument with "SEED '" & Seed_Text & "' is not an unsigned 64-bit integer";
      end;
      for Support of Samples.All_Types loop
         Put_Line (ROSIDL.Typesupport.DDS_Type_Name (Support) & " "
                   & Samples.Hex (Encode (Samples.Random_Message (Support, Seed,
                                                                  ASCII_Text => True),
                                          Little_Endian)));
      end loop;
   end Put_Random;

   type Recoder_Kind is (Dynamic_Codec, Generated_Codecs);

   type Bytes_Access is access Ada.Streams.Stream_Element_Array;
   procedure Free is new Ada.Unchecked_Deallocation
     (Ada.Streams.Stream_Element_Array, Bytes_Access);

   procedure Reencode (Recoder : Recoder_Kind) is
      use type ROSIDL.Static.Registries.Type_Entries;
      Types : constant Samples.Support_Vectors.Vector :=
        (if Recoder = Dynamic_Codec then Samples.All_Types
         else Samples.Support_Vectors.Empty_Vector);
      Generated : constant ROSIDL.Static.Registries.Type_Entries :=
        ROSIDL.Static.Bundled_Types.Types & ROSIDL.Static.Test_Types.Types;

      --  Name's data re-encoded little-endian, or "" when Name has no codec.
      function Recoded (Name : String; Data : Ada.Streams.Stream_Element_Array) return String is
      begin
         case Recoder is
            when Dynamic_Codec =>
               for Support of Types loop
                  if ROSIDL.Typesupport.DDS_Type_Name (Support) = Name then
                     return Samples.Hex (Encode (Decode (Support, Data), Little_Endian));
                  end if;
               end loop;
            when Generated_Codecs =>
               for T of Generated loop
                  if T.DDS_Type_Name.all = Name then
                     return Samples.Hex (T.Recode (Data, Little_Endian));
                  end if;
               end loop;
         end case;
         return "";
      end Recoded;

      function Unknown return String is
        (if Recoder = Dynamic_Codec then " ERROR unknown type" else " NONE");
   begin
      while not End_Of_File loop
         declare
            Line  : constant String := Get_Line;
            Found_Space : constant Natural := Ada.Strings.Fixed.Index (Line, " ");
            Space : constant Natural :=
              (if Found_Space = 0 then Line'Last + 1 else Found_Space);
            --  A line without hex is a name with no data (a Decode_Error).
            Name  : constant String := Line (Line'First .. Space - 1);
         begin
            declare
               Data : Bytes_Access :=
                 new Ada.Streams.Stream_Element_Array'
                   (Samples.From_Hex (Line (Space + 1 .. Line'Last)));
               --  On the heap, exactly sized: under valgrind, a read past its
               --  end is an error (the secondary stack would hide it).
            begin
               declare
                  Result : constant String := Recoded (Name, Data.all);
               begin
                  Put_Line (Name & (if Result = "" then Unknown else " " & Result));
               end;
               Free (Data);
            exception
               when E : ROSIDL.Decode_Error | ROSIDL.Encode_Error =>
                  Put_Line (Name & " ERROR " & Ada.Exceptions.Exception_Message (E));
                  Free (Data);
               when E : others =>
                  --  A decoder bug on malformed bytes (the fuzzer's finding):
                  --  the line says so and the batch goes on.
                  Put_Line (Name & " INTERNAL " & Ada.Exceptions.Exception_Name (E)
                            & ": " & Ada.Exceptions.Exception_Message (E));
                  Free (Data);
            end;
         exception
            when E : Constraint_Error =>
               --  From_Hex's bad hex text.
               Put_Line (Name & " ERROR " & Ada.Exceptions.Exception_Message (E));
         end;
      end loop;
   end Reencode;

   procedure Check_Sample (Name : String) is
   begin
      if not Samples.Names.Contains (Name) then
         raise Bad_Argument with "unknown sample '" & Name & "' (cdr_tool list shows them)";
      end if;
   end Check_Sample;

   function Hex_Argument (Text : String) return Ada.Streams.Stream_Element_Array is
   begin
      return Samples.From_Hex (Text);
   exception
      when E : Constraint_Error =>
         raise Bad_Argument with "HEX: " & Ada.Exceptions.Exception_Message (E);
   end Hex_Argument;

   procedure Usage is
   begin
      Put_Line (Standard_Error,
                "usage: cdr_tool list | encode NAME [be] | image NAME"
                & " | decode NAME HEX | types | random SEED [user]"
                & " | reencode [user|typed]");
      Set_Exit_Status (Failure);
   end Usage;

begin
   if Argument_Count = 1 and then Argument (1) = "types" then
      Put_Types;
   elsif Argument_Count in 2 .. 3 and then Argument (1) = "random"
     and then (Argument_Count = 2 or else Argument (3) = "user")
   then
      if Argument_Count = 3 then
         Samples.Use_User_Interfaces;
      end if;
      Put_Random (Argument (2));
   elsif Argument_Count = 1 and then Argument (1) = "reencode" then
      Reencode (Dynamic_Codec);
   elsif Argument_Count = 2 and then Argument (1) = "reencode" and then Argument (2) = "user" then
      Samples.Use_User_Interfaces;
      Reencode (Dynamic_Codec);
   elsif Argument_Count = 2 and then Argument (1) = "reencode" and then Argument (2) = "typed"
   then
      Reencode (Generated_Codecs);
   elsif Argument_Count = 1 and then Argument (1) = "list" then
      for N of Samples.Names loop
         Put_Line (N);
      end loop;
   elsif Argument_Count in 2 .. 3 and then Argument (1) = "encode"
     and then (Argument_Count = 2 or else Argument (3) = "be")
   then
      Check_Sample (Argument (2));
      Put_Line (Samples.Hex
        (Samples.Encode_Sample
           (Argument (2),
            (if Argument_Count = 3 and then Argument (3) = "be" then Big_Endian
             else Little_Endian))));
   elsif Argument_Count = 2 and then Argument (1) = "image" then
      Check_Sample (Argument (2));
      Put_Image (ROSIDL.Dynamic.Image (Samples.Make (Argument (2))));
   elsif Argument_Count = 3 and then Argument (1) = "decode" then
      Check_Sample (Argument (2));
      declare
         Msg  : ROSIDL.Dynamic.Message := Samples.Make (Argument (2));
         Data : constant Ada.Streams.Stream_Element_Array := Hex_Argument (Argument (3));
         Header : Request_Header;
      begin
         if Samples.Is_Request (Argument (2)) then
            Decode (Data, Msg, Header);
            Put_Line ("# guid" & Header.GUID'Image & " seq" & Header.Sequence'Image);
         else
            Decode (Data, Msg);
         end if;
         Put_Image (ROSIDL.Dynamic.Image (Msg));
      exception
         when E : ROSIDL.Decode_Error =>
            Put_Line (Standard_Error, "Decode_Error: "
                      & Ada.Exceptions.Exception_Message (E));
            Set_Exit_Status (2);
      end;
   else
      Usage;
   end if;
exception
   when E : Bad_Argument =>
      Put_Line (Standard_Error, "cdr_tool: " & Ada.Exceptions.Exception_Message (E));
      Set_Exit_Status (Failure);
   when E : others =>
      --  Last resort: a bug, reported in one line instead of a traceback.
      Put_Line (Standard_Error, "cdr_tool: internal error: " & Ada.Exceptions.Exception_Name (E)
                & ": " & Ada.Exceptions.Exception_Message (E));
      Set_Exit_Status (Failure);
end CDR_Tool;
