"""Team members in separate processes on loopback: when a robot's process
is killed (SIGKILL: it says nothing), the others learn of the loss from DDS
liveliness -- its presence writer's lease lapses -- and re-allocate its
unfinished tasks; the mission is finished by the survivors. (Members in one
process are expired on silence instead: Cyclone applies no lease to its own
participant's writers; this test covers the cross-process path.)"""
import os
import pathlib
import re
import signal
import subprocess
import time

import pubsub_support  # noqa: F401  (loopback CYCLONEDDS_URI, own domain when run alone)

REPO = pathlib.Path(__file__).resolve().parents[2]
SANCTA = REPO / "bin" / "sancta"
MISSION = REPO / "share" / "missions" / "office-team.xml"


def wait_for(pattern, path, timeout):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        text = path.read_text() if path.exists() else ""
        found = re.search(pattern, text, re.MULTILINE)
        if found:
            return found
        time.sleep(0.2)
    return None


def test_killed_robot_process_is_lost_by_liveliness(tmp_path):
    team = f"live{os.getpid()}"
    procs = {}
    logs = {}

    def start(name, *args):
        logs[name] = tmp_path / f"{name}.log"
        procs[name] = subprocess.Popen(
            [str(SANCTA), "team-agent", "--team", team, "--lease", "1.0", "--for", "150", *args],
            stdout=open(logs[name], "w"), stderr=subprocess.STDOUT, cwd=REPO)

    try:
        for i in (1, 2, 3):
            start(f"r{i}", "--id", f"r{i}", "--x", str(i * 3), "--y", "10", "--rate", "4")
        start("operator", "--operator", str(MISSION))
        op = logs["operator"]
        assert wait_for(r"round [0-9]+ robots r1,r2,r3 ", op, 60), op.read_text()
        assert wait_for(r"r3: did", logs["r3"], 60), logs["r3"].read_text()
        procs["r3"].send_signal(signal.SIGKILL)
        killed = time.monotonic()
        assert wait_for(r"round [0-9]+ robots r1,r2 ", op, 30), op.read_text()
        noticed = time.monotonic() - killed
        print(f"loss of r3 noticed (re-allocation round) {noticed:.2f} s after SIGKILL")
        procs["operator"].wait(timeout=150)
        text = op.read_text()
        assert procs["operator"].returncode == 0, text
        assert "operator: all done" in text
        tasks = len(re.findall(r"^done ", text, re.MULTILINE))
        listed = len(re.findall(r"<(goto|explore|choose) ", MISSION.read_text()))
        assert tasks == listed, text
        # A 1 s lease: the loss is noticed in seconds, long before Cyclone's
        # participant lease (10 s by default) would remove the process.
        assert noticed < 8.0, f"loss noticed after {noticed:.1f} s"
    finally:
        for p in procs.values():
            if p.poll() is None:
                p.kill()
            p.wait()
