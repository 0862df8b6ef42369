"""A team node's DDS participant lease (sancta/team/sancta-team-networks.ads).

A peer that dropped a participant (it heard nothing from it for its lease:
a cut link) finds it again only at its next announcement, which Cyclone
sends every 0.8 x the participant lease (every 8 s with the default 10 s
lease). After a healed cut the team had finished and left before a robot
was found again (tests/netns/team-netns.sh failed so). So the first team
network of a process creates the participant with a lease of 2 x the team
lease (2 .. 10 s). Checked here from a Python Cyclone peer on loopback: a
team agent with a 1 s team lease, stopped by SIGSTOP (it sends nothing), is
dropped by the peer within its 2 s lease (with the default lease it would
take 10 s), and is found again once it runs again."""
import os
import signal
import subprocess
import time

import pubsub_support as ps
from cyclonedds.builtin import BuiltinDataReader, BuiltinTopicDcpsParticipant
from cyclonedds.core import InstanceState

SANCTA = ps.BIN / "sancta"


def others(parts, own_key):
    """(key, alive) of each participant sample taken now, except our own."""
    return [(s.key, s.sample_info.instance_state == InstanceState.Alive)
            for s in parts.take(N=100) if s.key != own_key]


def wait_state(parts, own_key, key, alive, timeout, exclude=frozenset()):
    """Seconds until `key` (or any other participant not in `exclude` when
    None) is seen in state `alive`; None when it is not within `timeout`."""
    start = time.monotonic()
    while time.monotonic() - start < timeout:
        for k, a in others(parts, own_key):
            if (k == key if key is not None else k not in exclude) and a == alive:
                return time.monotonic() - start, k
        time.sleep(0.05)
    return None, None


def test_stopped_team_agent_is_dropped_within_its_participant_lease(tmp_path):
    dp = ps.participant()
    parts = BuiltinDataReader(dp, BuiltinTopicDcpsParticipant)
    own_key = dp.guid
    log = tmp_path / "agent.log"
    # Participants alive before the agent starts (a peer of an earlier test
    # still shutting down) are not the agent's.
    time.sleep(1.0)
    before = {k for k, _ in others(parts, own_key)}
    agent = subprocess.Popen(
        [str(SANCTA), "team-agent", "--team", f"rediscovery{os.getpid()}", "--id", "r1",
         "--x", "0", "--y", "0", "--lease", "1.0", "--for", "60"],
        stdout=open(log, "w"), stderr=subprocess.STDOUT)
    try:
        seen, key = wait_state(parts, own_key, None, True, 20, exclude=before)
        assert seen is not None, "the team agent's participant was never discovered"
        time.sleep(1.0)
        others(parts, own_key)  # drop the samples of the start
        agent.send_signal(signal.SIGSTOP)
        dropped, _ = wait_state(parts, own_key, key, False, 8)
        print(f"stopped agent dropped after {dropped} s")
        assert dropped is not None, (
            "a team agent silent for 8 s was not dropped: its participant lease is not"
            " 2 x its team lease (1 s)")
        assert dropped < 5.0, f"dropped only after {dropped:.1f} s (lease 2 s)"
        agent.send_signal(signal.SIGCONT)
        back, _ = wait_state(parts, own_key, key, True, 10)
        print(f"found again {back} s after SIGCONT")
        assert back is not None, "the agent was not found again after SIGCONT"
    finally:
        agent.send_signal(signal.SIGCONT)
        agent.terminate()
        try:
            agent.wait(timeout=5)
        except subprocess.TimeoutExpired:
            agent.kill()
            agent.wait()
