"""Writes a rosbag2 sqlite3 bag file (.db3) in the table layout of a given
storage schema version, for the tests and the fuzzer's seeds (facts from
rosbag2_storage_sqlite3: version 1 has no schema table and no
offered_qos_profiles; 2 adds offered_qos_profiles; 3 (Humble) the schema and
metadata tables; 4 type_description_hash).

Example:
    import rosbag2_db3
    rosbag2_db3.write("bag_0.db3", 3,
                      [(1, "/chatter", "std_msgs/msg/String", qos_yaml)],
                      [(1, 1_000_000_000, cdr_bytes)])
"""
import sqlite3


def write(path, schema_version, topics, messages, vacuum=False):
    """topics: (id, name, type, offered_qos_profiles text; ignored below
    version 2); messages: (topic_id, timestamp in ns, data bytes), inserted
    in this order. The file must not exist yet."""
    db = sqlite3.connect(path)
    has_qos = schema_version >= 2
    if schema_version >= 3:
        db.execute("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY,"
                   " ros_distro TEXT NOT NULL)")
        db.execute("INSERT INTO schema VALUES (?, 'humble')", (schema_version,))
        db.execute("CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER"
                   " NOT NULL, metadata TEXT NOT NULL)")
    db.execute("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT"
               " NOT NULL, serialization_format TEXT NOT NULL"
               + (", offered_qos_profiles TEXT NOT NULL" if has_qos else "")
               + (", type_description_hash TEXT NOT NULL" if schema_version >= 4 else "")
               + ")")
    db.execute("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL,"
               " timestamp INTEGER NOT NULL, data BLOB NOT NULL)")
    db.execute("CREATE INDEX timestamp_idx ON messages (timestamp ASC)")
    for topic_id, name, type_name, qos in topics:
        extra = ([qos] if has_qos else []) + ([""] if schema_version >= 4 else [])
        db.execute("INSERT INTO topics VALUES (?, ?, ?, 'cdr'" + ", ?" * len(extra) + ")",
                   [topic_id, name, type_name] + extra)
    db.executemany("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)",
                   messages)
    db.commit()
    if vacuum:
        db.execute("VACUUM")
    db.close()
    return path
