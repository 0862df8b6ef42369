"""Graph presence: a Python peer reads ros_discovery_info
(rmw_dds_common/msg/ParticipantEntitiesInfo) and finds the Ada node with the
gids of its endpoints, matched against DDS built-in discovery data; gids are
24 bytes (Humble, default) or 16 (ROS_DISTRO=jazzy)."""
import os
import subprocess
import time
from dataclasses import dataclass, field

import pytest
from cyclonedds.builtin import (BuiltinDataReader, BuiltinTopicDcpsParticipant,
                                BuiltinTopicDcpsPublication, BuiltinTopicDcpsSubscription)
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.annotations import final
from cyclonedds.idl.types import array, bounded_str, sequence, uint8

import pubsub_support as ps
from cyclonedds.core import Policy


def gid_types(size):
    @final
    @dataclass
    class Gid_(IdlStruct, typename="rmw_dds_common::msg::dds_::Gid_"):
        data: array[uint8, size] = field(default_factory=lambda: [0] * size)

    @final
    @dataclass
    class NodeEntitiesInfo_(IdlStruct, typename="rmw_dds_common::msg::dds_::NodeEntitiesInfo_"):
        node_namespace: bounded_str[256] = ""
        node_name: bounded_str[256] = ""
        reader_gid_seq: sequence[Gid_] = field(default_factory=list)
        writer_gid_seq: sequence[Gid_] = field(default_factory=list)

    @final
    @dataclass
    class ParticipantEntitiesInfo_(
            IdlStruct, typename="rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"):
        gid: Gid_ = field(default_factory=Gid_)
        node_entities_info_seq: sequence[NodeEntitiesInfo_] = field(default_factory=list)

    return ParticipantEntitiesInfo_


@pytest.mark.parametrize("distro,size", [("humble", 24), ("jazzy", 16)])
def test_discovery_info(distro, size):
    dp = ps.participant()
    info_type = gid_types(size)
    rd = ps.reader(dp, "ros_discovery_info", info_type, depth=100, transient_local=True)
    pubs = BuiltinDataReader(dp, BuiltinTopicDcpsPublication)
    subs = BuiltinDataReader(dp, BuiltinTopicDcpsSubscription)
    parts = BuiltinDataReader(dp, BuiltinTopicDcpsParticipant)
    env = dict(os.environ, ROS_DISTRO=distro)
    ada = subprocess.Popen(
        [str(ps.BIN / "pubsub_peer"), "echo", "std_msgs", "String", "/graph_in",
         "/graph_out", "1"], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        text=True)
    try:
        node = None
        infos = []
        deadline = time.monotonic() + 15
        while time.monotonic() < deadline and node is None:
            infos.extend(ps.take(rd))
            for info in reversed(infos):
                found = [n for n in info.node_entities_info_seq
                         if n.node_name == "pubsub_peer" and n.node_namespace == "/"]
                if found and found[0].reader_gid_seq and found[0].writer_gid_seq:
                    node, whole = found[0], info
                    break
            time.sleep(0.05)
        assert node is not None, f"pubsub_peer not in ros_discovery_info: {infos}"
        # Gids: the DDS GUID, zero-padded to the layout's size.
        for gid in [whole.gid] + node.reader_gid_seq + node.writer_gid_seq:
            assert len(gid.data) == size
            assert all(b == 0 for b in gid.data[16:])
        writer_gids = {bytes(g.data[:16]) for g in node.writer_gid_seq}
        reader_gids = {bytes(g.data[:16]) for g in node.reader_gid_seq}
        # ... and they are the endpoints DDS discovery reports for the topics
        # (the latest announcement: the node's parameter services come first).
        time.sleep(0.5)
        for info in infos + list(ps.take(rd)):
            found = [n for n in info.node_entities_info_seq
                     if n.node_name == "pubsub_peer" and n.node_namespace == "/"]
            if found:
                node, whole = found[0], info
        writer_gids = {bytes(g.data[:16]) for g in node.writer_gid_seq}
        reader_gids = {bytes(g.data[:16]) for g in node.reader_gid_seq}
        publications = {p.key.bytes: p for p in pubs.take(N=500)}
        subscriptions = {s.key.bytes: s for s in subs.take(N=500)}
        participants = {p.key.bytes: p for p in parts.take(N=500)}
        # Only the Ada participant's endpoints: a peer of an earlier test may
        # still be alive in this domain with the same topics.
        ada_key = bytes(whole.gid.data[:16])
        out_writer = [k for k, p in publications.items()
                      if p.topic_name == "rt/graph_out" and p.participant_key.bytes == ada_key]
        in_reader = [k for k, s in subscriptions.items()
                     if s.topic_name == "rt/graph_in" and s.participant_key.bytes == ada_key]
        assert out_writer and out_writer[0] in writer_gids, (out_writer, writer_gids)
        assert in_reader and in_reader[0] in reader_gids, (in_reader, reader_gids)
        assert bytes(whole.gid.data[:16]) in participants
        # A ROS 2 participant: USER_DATA "enclave=/;".
        ada_part = participants[bytes(whole.gid.data[:16])]
        assert ada_part.qos[Policy.Userdata].data == b"enclave=/;"
        assert publications[out_writer[0]].type_name == "std_msgs::msg::dds_::String_"
        # Jazzy endpoints announce the REP 2011 type hash Jazzy computes.
        def user_data(endpoint):
            policy = endpoint.qos[Policy.Userdata] if Policy.Userdata in endpoint.qos else None
            return policy.data if policy is not None else b""
        info_writer = [p for p in publications.values()
                       if p.topic_name == "ros_discovery_info"
                       and p.participant_key.bytes == bytes(whole.gid.data[:16])]
        assert info_writer, "no ros_discovery_info writer of the Ada participant"
        if distro == "jazzy":
            assert user_data(publications[out_writer[0]]) == (
                b"typehash=RIHS01_"
                b"df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18;")
            assert user_data(subscriptions[in_reader[0]]) == (
                b"typehash=RIHS01_"
                b"df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18;")
            assert user_data(info_writer[0]) == (
                b"typehash=RIHS01_"
                b"91a0593bacdcc50ea9bdcf849a938b128412cc1ea821245c663bcd26f83c295e;")
        else:
            assert b"typehash" not in user_data(publications[out_writer[0]])
            assert b"typehash" not in user_data(info_writer[0])
    finally:
        ada.kill()
        ada.communicate()
