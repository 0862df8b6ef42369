--  For generated code (ROSIDL.Static.Impl): the codec of each ROS 2
--  primitive type, as the generated code calls them
--  (ROSIDL.Static.Impl.Codecs.Float64_Codec.Put (B, C, V)).
with Ada.Streams;
with ROSIDL.Static.Impl.Wire.Primitives;

package ROSIDL.Static.Impl.Codecs is

   subtype Bytes is Ada.Streams.Stream_Element_Array;

   package UInt8_Codec is new Wire.Primitives (UInt8, UInt8_Array);
   package Int8_Codec is new Wire.Primitives (Int8, Int8_Array);
   package UInt16_Codec is new Wire.Primitives (UInt16, UInt16_Array);
   package Int16_Codec is new Wire.Primitives (Int16, Int16_Array);
   package UInt32_Codec is new Wire.Primitives (UInt32, UInt32_Array);
   package Int32_Codec is new Wire.Primitives (Int32, Int32_Array);
   package UInt64_Codec is new Wire.Primitives (UInt64, UInt64_Array);
   package Int64_Codec is new Wire.Primitives (Int64, Int64_Array);
   package Float32_Codec is new Wire.Primitives (Float32, Float32_Array);
   package Float64_Codec is new Wire.Primitives (Float64, Float64_Array);

   package Bool_Codec is
      --  One byte, 0 or 1; any byte other than 0 decodes as True (as the
      --  dynamic codec and rmw_cyclonedds read it).
      procedure Put (B : in out Bytes; C : in out Wire.Cursor; V : Boolean)
        with Inline;
      procedure Get (B : Bytes; C : in out Wire.Cursor; V : out Boolean; What : String)
        with Inline;
      procedure Put_Array
        (B : in out Bytes; C : in out Wire.Cursor; Items : Bool_Array);
      procedure Get_Array
        (B : Bytes; C : in out Wire.Cursor; Items : out Bool_Array; What : String);
   end Bool_Codec;

end ROSIDL.Static.Impl.Codecs;
