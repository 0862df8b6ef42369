--  ROS 2 bags as rosbag2 writes them with its MCAP storage: a directory
--  holding metadata.yaml and bag_0.mcap, bag_1.mcap... (one more per size or
--  duration split). MCAP's ros2 profile: one schema per message type
--  ("ros2msg": the type's .msg text, then each nested type's after a line of
--  80 '=' and "MSG: pkg/msg/Name"), one channel per topic with message
--  encoding "cdr" and metadata offered_qos_profiles (the publishers' QoS in
--  rosbag2's YAML). RCL.Bags.Recorders records live topics; `rclada bag`
--  is the command line. Bag_Reader also reads rosbag2's sqlite3 storage
--  (Humble's default: bag_0.db3... SQLite databases, read-only through
--  RCL.SQLite): tables topics (id, name, type, serialization_format, and
--  offered_qos_profiles from schema version 2) and messages (id, topic_id,
--  timestamp, data); the schema, metadata and message_definitions tables of
--  schema versions 3 and 4 are not needed to play.
--  Example:
--     W : Bag_Writer;
--     W.Create ("out/run", Compression => RCL.MCAP.Zstd);
--     T : constant Topic_Index := W.Add_Topic ("/chatter", "std_msgs/msg/String",
--                                              Offered_QoS_Text ([RCL.QoS.Default]));
--     W.Write (T, Receive_Time, Cdr_Bytes);
--     W.Close;                  --  writes metadata.yaml
--
--     R : Bag_Reader;
--     R.Open ("out/run");      --  a bag directory or one .mcap file
--     R.Iterate (Play'Access);
with Ada.Finalization;
with Interfaces;
with RCL.MCAP;
with RCL.QoS;

private with Ada.Containers.Indefinite_Vectors;
private with Ada.Containers.Vectors;
private with Ada.Strings.Unbounded;
private with RCL.MCAP.Writers;
private with RCL.MCAP.Readers;
private with RCL.Zstd;

package RCL.Bags is

   use type Interfaces.Unsigned_64;

   Bag_Error : exception;
   --  A bag that cannot be written or read; the message names the path.
   --  Defects inside an MCAP file raise RCL.MCAP.Format_Error.

   subtype Time_Stamp is RCL.MCAP.Time_Stamp;

   function Message_Definition_Text (Type_Name : String) return String;
   --  The ros2msg schema of "pkg/msg/Name": its definition, then every type
   --  it nests (depth first, each once) after the rosbag2 delimiter.
   --  ROSIDL.Unknown_Type when the interface is not on the path.

   type Profile_Array is array (Positive range <>) of RCL.QoS.Profile;

   function Offered_QoS_Text (Profiles : Profile_Array) return String;
   --  rosbag2 (Humble) YAML of the publishers' QoS: "- history: 1\n  depth:
   --  10\n  reliability: 1\n  durability: 2\n ...".

   function Playback_QoS (Offered : String) return RCL.QoS.Profile;
   --  What rosbag2 play offers for a topic recorded with Offered: reliable
   --  unless a publisher was best effort, transient local when every one
   --  was, depth 10 (or the largest recorded depth). The policies as
   --  numbers (rosbag2's metadata version 8 and before: Humble) or names
   --  (version 9 on: Jazzy, "best_effort", "transient_local"). Default when
   --  Offered is empty or not understood.

   function Offered_QoS_Problem (Offered : String) return String;
   --  "" when Playback_QoS understands Offered, else what it does not:
   --  "profile 1: durability 'latched' is no durability policy", or the YAML
   --  error ("offered_qos_profiles:3:5: ...").

   --  Writing ---------------------------------------------------------------------

   type Bag_Writer is new Ada.Finalization.Limited_Controlled with private;

   type Topic_Index is new Positive;

   type Bag_Compression is (No_Compression, File_Compression, Message_Compression);
   --  rosbag2's own compression (ros2 bag record --compression-mode, with
   --  --compression-format zstd), besides MCAP's chunk compression: each
   --  file compressed whole once closed (bag_0.mcap.zstd), or each
   --  message's data one zstd frame.

   procedure Create
     (This         : in out Bag_Writer;
      Directory    : String;
      Compression  : RCL.MCAP.Compression_Kind := RCL.MCAP.Zstd;
      Max_Bytes    : Interfaces.Unsigned_64 := 0;
      Max_Duration : Duration := 0.0;
      Background   : Boolean := False;
      Mode         : Bag_Compression := No_Compression)
     with Pre => not This.Is_Open;
   --  Makes Directory (Bag_Error when it exists already, as ros2 bag record)
   --  and its first file. Max_Bytes / Max_Duration (0: none) start a new
   --  file once the current one is that large / spans that long.
   --  Background: each file's full chunks are compressed and written by a
   --  task while the next fills (RCL.MCAP.Writers.Create). Mode:
   --  metadata.yaml then says compression_mode FILE or MESSAGE,
   --  compression_format zstd, as rosbag2 writes it (File_Compression
   --  compresses each file as it is closed, streaming, then deletes it).

   function Is_Open (This : Bag_Writer) return Boolean;

   function Add_Topic
     (This : in out Bag_Writer; Name, Type_Name, Offered_QoS : String) return Topic_Index
     with Pre => This.Is_Open;
   --  A topic ("/chatter", "std_msgs/msg/String"); its schema is
   --  Message_Definition_Text (Type_Name), or empty when the interface is
   --  unknown here (the messages are still recorded).

   procedure Write
     (This         : in out Bag_Writer;
      Topic        : Topic_Index;
      Receive_Time : Time_Stamp;
      Data         : RCL.MCAP.Byte_Array;
      Publish_Time : Time_Stamp := 0)
     with Pre => This.Is_Open;
   --  Data: CDR with its encapsulation header.

   function Message_Count (This : Bag_Writer) return Interfaces.Unsigned_64;
   function File_Count (This : Bag_Writer) return Natural;

   procedure Close (This : in out Bag_Writer);
   --  Closes the last file and writes metadata.yaml.

   overriding procedure Finalize (This : in out Bag_Writer);

   --  Reading ---------------------------------------------------------------------

   type Bag_Reader is new Ada.Finalization.Limited_Controlled with private;

   procedure Open (This : in out Bag_Reader; Path : String; Recover : Boolean := False);
   --  A bag directory (the files metadata.yaml lists, else its *.mcap files
   --  in name order, else its *.db3 files) or one .mcap or .db3 file.
   --  Bag_Error when there is no such file; RCL.MCAP.Format_Error (with the
   --  byte offset) when an MCAP file is bad; Recover reads truncated MCAP
   --  files up to their last complete record. A SQLite file (known by its
   --  header, whatever its name) that is no rosbag2 bag raises Bag_Error
   --  naming the file and the table, column or row ("run_0.db3: messages
   --  row 17: topic_id 9 names no topic"); one SQLite cannot read, with
   --  SQLite's own message ("run_0.db3: database disk image is malformed").
   --  rosbag2's zstd compression is read: a file compressed whole
   --  (compression_mode file, "run_0.db3.zstd", "run_0.mcap.zstd"; known by
   --  its first bytes, whatever metadata.yaml says) is decompressed as a
   --  stream into a temporary file ($TMPDIR, else /tmp; one at a time,
   --  deleted by Close and Finalize) and read from there; messages
   --  compressed one by one (compression_mode message) are decompressed by
   --  Iterate. Bag_Error naming the file and byte for a corrupt or
   --  truncated zstd frame, a compression_format other than zstd, a file or
   --  message that metadata.yaml says is compressed and is not.

   function Topic_Count (This : Bag_Reader) return Natural;
   function Topic_Name (This : Bag_Reader; Topic : Topic_Index) return String;
   function Topic_Type (This : Bag_Reader; Topic : Topic_Index) return String;
   function Topic_QoS (This : Bag_Reader; Topic : Topic_Index) return String;
   --  The offered_qos_profiles text recorded ("" when none).
   function Topic_Message_Count
     (This : Bag_Reader; Topic : Topic_Index) return Interfaces.Unsigned_64;

   function Topic_Place (This : Bag_Reader; Topic : Topic_Index) return String;
   --  Where the topic's channel record is, for an error about the topic:
   --  "run/run_0.mcap: byte 345: channel 2" (the first file that has it);
   --  in a .db3 file its row of table topics ("run/run_0.db3: topics row 2").
   function Type_Place (This : Bag_Reader; Topic : Topic_Index) return String;
   --  Where its schema record is, for an error about the type:
   --  "run/run_0.mcap: byte 120: schema 1" (Topic_Place when it has none,
   --  and in a .db3 file).

   function Message_Count (This : Bag_Reader) return Interfaces.Unsigned_64;
   function Start_Time (This : Bag_Reader) return Time_Stamp;
   function End_Time (This : Bag_Reader) return Time_Stamp;
   function File_Count (This : Bag_Reader) return Natural;
   function File_Name (This : Bag_Reader; Index : Positive) return String;
   function Bytes (This : Bag_Reader) return Interfaces.Unsigned_64;
   function Compression (This : Bag_Reader) return String;
   --  Of the first MCAP file's chunks ("" when none or not MCAP).

   procedure Close (This : in out Bag_Reader);
   --  Deletes the temporary decompressed file, if any; Open may follow.

   overriding procedure Finalize (This : in out Bag_Reader);

   function Warning (This : Bag_Reader) return String;
   --  What Open could not use but read the bag without ("" when nothing):
   --  a metadata.yaml that does not parse ("run/metadata.yaml:3:7: ...";
   --  the directory's .mcap files are read instead).

   procedure Iterate
     (This    : in out Bag_Reader;
      Process : not null access procedure
        (Topic : Topic_Index; Receive_Time : Time_Stamp; Data : RCL.MCAP.Byte_Array));
   --  Every message, file after file, in receive-time order within a file
   --  (in a .db3 file, messages of one time in row order, as rosbag2).
   --  Data is decompressed first when it is a zstd frame (compression_mode
   --  message); Bag_Error when it is not one and metadata.yaml says it is.

   function Message_Place (This : Bag_Reader) return String;
   --  During Iterate, where the message being processed is, for an error
   --  about it: "run/run_0.mcap: byte 900: the chunk's uncompressed byte 56",
   --  "run/run_0.db3: messages row 17".

   function Info (This : Bag_Reader) return String;
   --  What "ros2 bag info" prints: files, size, storage, duration, start,
   --  end, messages, and a line per topic (type, count, serialization).

private

   use Ada.Strings.Unbounded;

   type Topic_Entry is record
      Name, Type_Name, QoS_Text : Unbounded_String;
      Count  : Interfaces.Unsigned_64 := 0;
      Channel : RCL.MCAP.Channel_Id := 0;
      --  In the writer's current file (0: not yet added to it); in the
      --  reader's first file that has the topic.
      Schema  : RCL.MCAP.Schema_Id := 0;
      File    : Natural := 0;
      Channel_At, Schema_At : Interfaces.Unsigned_64 := 0;
      --  The reader's: in that file, its schema and where the records are.
      Row : Interfaces.Integer_64 := 0;
      --  In a .db3 file: its row (rowid) in table topics.
   end record;
   package Topic_Vectors is new Ada.Containers.Vectors (Topic_Index, Topic_Entry);

   type Storage_Kind is (MCAP_Storage, SQLite_Storage);

   type File_Entry is record
      Name          : Unbounded_String;
      Storage       : Storage_Kind := MCAP_Storage;
      Whole_Zstd    : Boolean := False;
      --  Compressed whole (rosbag2's compression_mode file): read from a
      --  temporary decompressed copy.
      First, Last   : Time_Stamp := 0;
      Count         : Interfaces.Unsigned_64 := 0;
   end record;
   package File_Vectors is new Ada.Containers.Vectors (Positive, File_Entry);

   package Type_Vectors is new Ada.Containers.Indefinite_Vectors (Positive, String);

   type Bag_Writer is new Ada.Finalization.Limited_Controlled with record
      Directory    : Unbounded_String;
      Compression  : RCL.MCAP.Compression_Kind := RCL.MCAP.Zstd;
      Background   : Boolean := False;
      Max_Bytes    : Interfaces.Unsigned_64 := 0;
      Max_Span     : Time_Stamp := 0;
      File         : RCL.MCAP.Writers.Writer;
      Files        : File_Vectors.Vector;
      Topics       : Topic_Vectors.Vector;
      Schema_Types : Type_Vectors.Vector;
      --  The types whose schema the current file has, by schema id.
      Total        : Interfaces.Unsigned_64 := 0;
      Open         : Boolean := False;
      Mode         : Bag_Compression := No_Compression;
      Zipper       : RCL.Zstd.Compressor;
   end record;

   type Compression_Mode is (Not_Said, None_Said, File_Said, Message_Said);
   --  rosbag2's compression_mode in metadata.yaml (Not_Said: no
   --  metadata.yaml, or one without compression_mode).

   type Bag_Reader is new Ada.Finalization.Limited_Controlled with record
      Files       : File_Vectors.Vector;
      --  Full paths.
      Topics      : Topic_Vectors.Vector;
      Total       : Interfaces.Unsigned_64 := 0;
      First, Last : Time_Stamp := 0;
      Size        : Interfaces.Unsigned_64 := 0;
      Compression : Unbounded_String;
      Warning     : Unbounded_String;
      Recover     : Boolean := False;
      Current     : RCL.MCAP.Readers.Reader;
      Now_File    : Natural := 0;
      Now_Message : RCL.MCAP.Readers.Message;
      Now_Row     : Interfaces.Integer_64 := 0;
      --  During Iterate: the file and the message being processed (in a
      --  .db3 file, its row).
      Mode        : Compression_Mode := Not_Said;
      Plain_File  : Natural := 0;
      Plain_Path  : Unbounded_String;
      --  The one file compressed whole that is decompressed now (0: none),
      --  and where: a temporary file, deleted by Close and Finalize.
      Unzstd      : RCL.Zstd.Decompressor;
      --  Of messages compressed one by one (compression_mode message).
   end record;

end RCL.Bags;
