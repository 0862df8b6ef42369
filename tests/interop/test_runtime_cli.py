"""The `sancta check` and `sancta run` commands as a user runs them: exit
statuses, positioned diagnostics, the wiring outputs, Ctrl-C with the
components stopped in reverse start order, a watchdog abort."""
import os
import re
import select
import signal
import subprocess
import sys
import time

import pubsub_support as ps

SANCTA = str(ps.BIN / "sancta")
CONFIG = ps.REPO / "tests" / "data" / "config"
SHARE = ps.REPO / "share" / "config"


def sancta(*args, timeout=30):
    return subprocess.run([SANCTA, *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, cwd=ps.REPO)


def test_check_reports_errors_with_positions():
    r = sancta("check", CONFIG / "bad-unknown-component.xml")
    assert r.returncode == 1, r
    assert re.search(r"bad-unknown-component\.xml:4:16: error: unknown component 'odometri' "
                     r"\(did you mean 'odometry'\?\)", r.stderr), r.stderr


def test_check_prints_and_draws_the_wiring(tmp_path):
    r = sancta("check", SHARE / "listing-1.1.xml", "--output", tmp_path)
    assert r.returncode == 0, r
    assert re.search(r"odometric_pose\s+types\.pose\s+odometry#1\.pose\s+scan_matching#2\.pose",
                     r.stdout), r.stdout
    dot = (tmp_path / "listing-1.1.dot").read_text()
    assert "n_Ari_odometry_1 -> n_Ari_scan_matching_2" in dot, dot
    assert "warning: output 'corrected_pose'" in r.stderr


def test_run_stops_on_ctrl_c_in_reverse_order():
    proc = subprocess.Popen([SANCTA, "run", str(SHARE / "team.xml"), "--all",
                             "--level", "Ari=debug"], cwd=ps.REPO,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    # Ctrl-C only once both agents have started (a fixed delay is too short
    # on a loaded machine); give up after 30 s. Raw reads: select() does not
    # see what a text stream has already buffered.
    seen, deadline = b"", time.monotonic() + 30.0
    fd = proc.stdout.fileno()
    while not all(f"agent {a} started".encode() in seen for a in ("Ari", "Ben")):
        ready, _, _ = select.select([fd], [], [], max(deadline - time.monotonic(), 0))
        chunk = os.read(fd, 65536) if ready else b""
        if not chunk:
            proc.kill()
            raise AssertionError("agents did not start in time:\n" + seen.decode()
                                 + ps.finish(proc))
        seen += chunk
    proc.send_signal(signal.SIGINT)
    out = seen.decode() + ps.finish(proc)
    assert proc.returncode == 0, out
    assert "stopping: interrupted (Ctrl-C)" in out, out
    started = re.findall(r"\[Ari\] started (\S+)", out)
    stopped = re.findall(r"\[Ari\] stopped (\S+)", out)
    assert started == ["odometry#1", "scan_matching#2", "watchdog#3", "logger#4"], out
    assert stopped == list(reversed(started)), out
    assert "agent Ben stopped" in out


def test_run_watchdog_abort_fails():
    r = sancta("run", CONFIG / "good-watchdog-abort.xml", "--agent", "Ari", "--set", "feed=0",
               "--for", 10)
    assert r.returncode == 1, r
    assert "watchdog Ari/watchdog#2" in r.stderr, r.stderr


def test_run_refuses_a_wrong_configuration():
    r = sancta("run", CONFIG / "bad-type-connection.xml", "--all", "--for", 1)
    assert r.returncode == 1, r
    assert "nothing started" in r.stderr, r.stderr


def test_team_ends_on_sigterm(tmp_path):
    """`sancta team` (every agent in-process, on ROS 2) stops its agents and
    ends when sent SIGTERM, as `timeout` or a process manager does; it used
    to report an internal error and hang, its agents' tasks still running."""
    make = ps.REPO / "share" / "missions" / "make_campus.py"
    world = ps.REPO / "share" / "worlds" / "campus.yaml"
    text = subprocess.run([sys.executable, str(make), "5", "12"], capture_output=True,
                          text=True, check=True).stdout
    mission = tmp_path / "campus-5.xml"
    mission.write_text(text.replace('world="../worlds/campus.yaml"', f'world="{world}"'))
    proc = subprocess.Popen([SANCTA, "team", str(mission), "--rate", "1", "--no-kill",
                             "--out", str(tmp_path / "out")], cwd=ps.REPO,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seen, deadline = b"", time.monotonic() + 60.0
    fd = proc.stdout.fileno()
    while b"first plan adopted" not in seen:
        ready, _, _ = select.select([fd], [], [], max(deadline - time.monotonic(), 0))
        chunk = os.read(fd, 65536) if ready else b""
        if not chunk:
            proc.kill()
            raise AssertionError("no plan in time:\n" + seen.decode() + ps.finish(proc))
        seen += chunk
    proc.send_signal(signal.SIGTERM)
    out = seen.decode() + ps.finish(proc, timeout=20)
    assert "demo: interrupted (SIGINT or SIGTERM)" in out, out
    assert "internal error" not in out, out
    assert "makespan:" in out, out     # the summary of what was done
    assert proc.returncode == 0, out   # a requested stop, as `sancta run` on Ctrl-C
