"""Type hash of a generated user type in Jazzy layout (ROS_DISTRO=jazzy).

bin/typed_hash_peer makes endpoints of sancta_test_msgs/msg/Everything, a
type of tests/data/user_interfaces that the first run keeps off the
interface search path: a raw (untyped) publisher made first announces the
zero hash (all the search path gives), then the typed publisher and
subscription must announce, in the USER_DATA "typehash=" that a Python peer
reads from the DCPSPublication / DCPSSubscription built-in topics, the hash
the generated code carries (RCL registers it). The second run puts the
user folder on the search path: the raw publisher then announces the hash
the library computes from the .msg files at run time, which must equal the
generated one."""
import os
import re
import subprocess
import time

from cyclonedds.builtin import (BuiltinDataReader, BuiltinTopicDcpsPublication,
                                BuiltinTopicDcpsSubscription)
from cyclonedds.core import Policy

import pubsub_support as ps

ZERO_HASH = "RIHS01_" + "0" * 64
USER_FOLDER = ps.REPO / "tests" / "data" / "user_interfaces"


def user_data(endpoint):
    policy = endpoint.qos[Policy.Userdata] if Policy.Userdata in endpoint.qos else None
    return policy.data.decode() if policy is not None else ""


def announced_hashes(search_path):
    """Runs the peer with RCLADA_INTERFACE_PATH = search_path; returns the
    generated hash it prints and the typehash= values of its endpoints:
    {("pub" | "sub", "typed" | "untyped"): hash}."""
    topic = f"type_hash_{os.getpid()}_{len(search_path)}"
    env = dict(os.environ, ROS_DISTRO="jazzy", RCLADA_INTERFACE_PATH=search_path,
               AMENT_PREFIX_PATH="")
    dp = ps.participant()
    pubs = BuiltinDataReader(dp, BuiltinTopicDcpsPublication)
    subs = BuiltinDataReader(dp, BuiltinTopicDcpsSubscription)
    exe = ps.BIN / "typed_hash_peer"
    assert exe.exists(), f"{exe} not built"
    peer = subprocess.Popen([str(exe), f"/{topic}", "20"], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        first = peer.stdout.readline().strip()
        assert first.startswith("type_hash "), first + peer.stdout.read()
        generated = first.split()[1]
        found = {}
        label = {f"rt/{topic}": "typed", f"rt/{topic}_untyped": "untyped"}
        wanted = {("pub", "typed"), ("pub", "untyped"), ("sub", "typed")}
        deadline = time.monotonic() + 15
        while time.monotonic() < deadline and not wanted <= found.keys():
            for kind, reader in (("pub", pubs), ("sub", subs)):
                for e in reader.take(N=200):
                    if (kind, label.get(e.topic_name)) in wanted:
                        assert e.type_name == "sancta_test_msgs::msg::dds_::Everything_"
                        data = user_data(e)
                        match = re.fullmatch(r"typehash=(RIHS01_[0-9a-f]{64});", data)
                        assert match, f"{kind} {e.topic_name}: USER_DATA {data!r}"
                        found[(kind, label[e.topic_name])] = match.group(1)
            time.sleep(0.05)
        assert wanted <= found.keys(), f"endpoints seen: {found}"
        return generated, found
    finally:
        peer.kill()
        peer.communicate()


def test_user_type_off_the_search_path_announces_its_generated_hash():
    path = os.environ.get("RCLADA_INTERFACE_PATH", "")
    assert str(USER_FOLDER) not in path
    generated, hashes = announced_hashes(path)
    assert re.fullmatch(r"RIHS01_[0-9a-f]{64}", generated) and generated != ZERO_HASH
    # Without registration: the zero hash (the type is not on the path).
    assert hashes[("pub", "untyped")] == ZERO_HASH, hashes
    # Typed endpoints: the generated hash, registered by RCL.
    assert hashes[("pub", "typed")] == generated, hashes
    assert hashes[("sub", "typed")] == generated, hashes


def test_generated_hash_equals_the_hash_computed_from_the_definition():
    path = os.environ.get("RCLADA_INTERFACE_PATH", "")
    generated, hashes = announced_hashes(f"{USER_FOLDER}:{path}" if path else str(USER_FOLDER))
    # The raw endpoint comes first: its hash is computed from the .msg files
    # on the search path (ROSIDL.Type_Hashes at run time).
    assert hashes[("pub", "untyped")] == generated, hashes
    assert hashes[("pub", "typed")] == generated and hashes[("sub", "typed")] == generated
