"""The broken-input corpus (issue 19, item 5): tests/data/broken/cases.txt
lists configurations, missions, TSPLIB files, worlds and command lines that
are wrong; each must end within its time limit with the expected non-zero
exit status, name where the problem is (file:line:column, or the argument),
and print no traceback. SANCTA_BROKEN_BIN=folder runs the corpus against
other binaries (the note's before/after counts)."""
import os
import pathlib
import shlex
import signal
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data" / "broken"
BIN = pathlib.Path(os.environ.get("SANCTA_BROKEN_BIN", REPO / "bin"))
TIME_LIMIT = 15.0
TRACEBACK = ("raised ", "internal error", "Call stack", "CONSTRAINT_ERROR", "STORAGE_ERROR",
             "PROGRAM_ERROR", "TASKING_ERROR", "Traceback")


def load_cases():
    cases = []
    for number, line in enumerate((DATA / "cases.txt").read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cid, argv, code, expect = (part.strip() for part in line.split(" | "))
        cases.append(pytest.param(argv, code, [e for e in expect.split(" ;; ") if e],
                                  id=cid))
    return cases


@pytest.fixture(scope="module")
def tmp(tmp_path_factory):
    d = tmp_path_factory.mktemp("broken")
    robot = '<robot id="r1" x="1" y="1"/>\n'
    (d / "huge-attribute.xml").write_text(
        '<team>\n  <agent id="a1" kind="robot">\n    <component name="odometry" v="'
        + "9" * (1024 * 1024) + '"/>\n  </agent>\n</team>\n')
    (d / "huge-file.xml").write_text(
        "<team>\n" + ("<!-- " + "x" * 1000 + " -->\n") * 40000 + "</team>\n")
    (d / "many-agents.xml").write_text(
        "<team>\n" + "".join(f'  <agent id="a{i}" kind="robot"><component name="odometry"/>'
                             f"</agent>\n" for i in range(20000)) + "</team>\n")
    (d / "many-tasks.xml").write_text(
        '<mission scale="100">\n' + robot + "".join(
            f'<task id="t{i}" x="{i % 1000}" y="{i // 1000}"/>\n' for i in range(200000))
        + "</mission>\n")
    world = REPO / "share" / "worlds" / "office.yaml"
    (d / "team-many-tasks.xml").write_text(
        f'<mission name="m" world="{world}">\n<robot id="r1" x="2.5" y="10"/>\n'
        '<robot id="r2" x="6" y="10"/>\n' + "".join(
            f'<goto id="t{i}" x="{1 + (i % 280) / 10}" y="{1 + (i // 280) % 180 / 10}"/>\n'
            for i in range(50000)) + "</mission>\n")
    (d / "many.tsp").write_text(
        "NAME : many\nTYPE : TSP\nDIMENSION : 2000000\nEDGE_WEIGHT_TYPE : EUC_2D\n"
        "NODE_COORD_SECTION\n" + "".join(f"{i} {i % 1000} {i // 1000}\n"
                                         for i in range(1, 2000001)) + "EOF\n")
    # Lines of 2 MB (the fuzzer's finding: STORAGE_ERROR in sancta-render).
    (d / "long-line.walls").write_text("resolution 0.05\nwall " + "x_" * (1 << 20) + "\n")
    (d / "long-line.yaml").write_text("image: room.pgm\nresolution: " + "5" * (1 << 21) + "\n")
    (d / "long-line-config.xml").write_text(
        '<team>\n  <agent id="a1" kind="robot">' + "x_" * (1 << 20)
        + '<component name="nosuch"/></agent>\n</team>\n')
    (d / "long-line-mission.xml").write_text(
        f'<mission name="m" world="{world}">\n<robot id="r1" x="2.5" y="10"/>\n<!-- '
        + "x_" * (1 << 20) + ' -->\n<goto id="t1" x="1" y="1.5"/>\n<goto id="t1" x="2" y="2"/>\n'
        "</mission>\n")
    # An unknown option named by 200 KB: "did you mean" took minutes (the
    # edit distances were computed once per allowed distance).
    (d / "long-option.xml").write_text(
        '<team>\n  <agent id="a1" kind="robot">\n    <component name="odometry" '
        + "x" * 200_000 + '="1"/>\n  </agent>\n</team>\n')
    (d / "long-line.csv").write_text("robot,x,y\n1,1,1\n1," + "9" * (1 << 21) + ",1\n")
    return d


def env():
    e = dict(os.environ)
    e["CYCLONEDDS_URI"] = "file://" + str(REPO / "share" / "cyclonedds-localhost.xml")
    e["ROS_LOCALHOST_ONLY"] = "1"
    e.setdefault("ROS_DOMAIN_ID", str(os.getpid() % 200 + 1))
    e["SANCTA_ROOT"] = str(REPO)
    e["RCLADA_ROOT"] = str(REPO)
    return e


@pytest.mark.parametrize("argv,code,expect", load_cases())
def test_broken_input(argv, code, expect, tmp):
    words = [w.replace("{data}", str(DATA)).replace("{repo}", str(REPO)).replace("{tmp}", str(tmp))
             for w in shlex.split(argv)]
    words[0] = str(BIN / words[0])
    # A session of its own: on a hang, or when it leaves children behind
    # (sancta demo starts sancta-sim and agents), the whole group is killed.
    p = subprocess.Popen(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         errors="replace", cwd=tmp, env=env(), start_new_session=True)
    try:
        stdout, stderr = p.communicate(timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        pytest.fail(f"hang: no end within {TIME_LIMIT} s: {argv}")
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    out = stdout + stderr
    shown = out[-2000:]
    assert p.returncode >= 0, f"killed by signal {-p.returncode}:\n{shown}"
    for bad in TRACEBACK:
        assert bad not in out, f"traceback ({bad}):\n{shown}"
    if code == "!0":
        assert p.returncode != 0, f"accepted silently (exit 0):\n{shown}"
    else:
        assert p.returncode == int(code), f"exit {p.returncode}, not {code}:\n{shown}"
    for e in expect:
        e = e.replace("{data}", str(DATA)).replace("{repo}", str(REPO)).replace("{tmp}", str(tmp))
        assert e in out, f"unclear: {e!r} not in the output:\n{shown}"


def test_cdr_tool_shows_a_wstring_code_point_utf8_cannot_encode():
    """A wstring from the wire holding a surrogate (U+D800): shown as U+FFFD
    (was "internal error: ENCODING_ERROR", one of cdr_tool's two causes of
    internal errors on mutated samples)."""
    sample = ("00010000010000000300000068000000e900000000d8000003000000610000006200"
              "0000630000000200000000000000010000007a000000")
    p = subprocess.run([str(BIN / "cdr_tool"), "decode", "wstrings", sample],
                       capture_output=True, text=True, timeout=TIME_LIMIT, env=env())
    out = p.stdout + p.stderr
    assert p.returncode == 0 and "w: h\u00e9\ufffd" in p.stdout, out
    assert not any(bad in out for bad in TRACEBACK), out


def test_map_image_path_with_folders(tmp_path):
    """A map YAML naming its image by a relative path with folders
    ("../maps/room.pgm") loads it (was "cannot write: invalid simple name":
    Ada.Directories.Compose takes simple names only)."""
    maps = tmp_path / "maps"
    maps.mkdir()
    (maps / "room.pgm").write_bytes((REPO / "tests" / "data" / "simulation" / "room.pgm").read_bytes())
    worlds = tmp_path / "worlds"
    worlds.mkdir()
    (worlds / "room.yaml").write_text("image: ../maps/room.pgm\nresolution: 0.05\n"
                                      "origin: [0, 0, 0]\n")
    p = subprocess.run([str(BIN / "sancta-render"), str(worlds / "room.yaml"), "--svg",
                        str(tmp_path / "w.svg")], capture_output=True, text=True,
                       timeout=TIME_LIMIT, env=env())
    assert p.returncode == 0 and (tmp_path / "w.svg").stat().st_size > 0, p.stdout + p.stderr


def test_far_trajectory_points_render(tmp_path):
    """Trajectory points a billion kilometres away are drawn outside the
    picture (were "rendering.adb:35 overflow check failed" for SVG and
    ":215" for PNG)."""
    csv = tmp_path / "far.csv"
    csv.write_text("robot,x,y\n1,1,1\n1,9e11,2\n2,-1e11,5\n2,3,-9.5e11\n")
    for kind in ("--svg", "--png"):
        out = tmp_path / ("w" + kind[1:].replace("-", "."))
        p = subprocess.run([str(BIN / "sancta-render"), str(REPO / "share" / "worlds" / "arena.walls"),
                            "--trajectories", str(csv), kind, str(out)],
                           capture_output=True, text=True, timeout=TIME_LIMIT, env=env())
        text = p.stdout + p.stderr
        assert p.returncode == 0 and out.stat().st_size > 0, text
        assert not any(bad in text for bad in TRACEBACK), text
