"""A short, deterministic run of scripts/fuzz_inputs.py (fixed seed, a dozen
mutated inputs per reader, no DDS): every reader refuses its mutated inputs
with a located error or accepts them, and nothing crashes, hangs or prints
an exception; the typed reader also compares the generated codecs with the
dynamic decoder on the same payloads. The long runs and their findings:
/work/notes/fuzz-s8.md."""
import pathlib
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
READERS = ("config,mission,team,tsp,world,walls,trajectories,pgm,definition,params,mcap,"
           "mcap-recover,cdr,typed")


def test_fuzz_smoke():
    p = subprocess.run([sys.executable, str(REPO / "scripts" / "fuzz_inputs.py"), "--seed", "19",
                        "--cases", "12", "--readers", READERS],
                       capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout + p.stderr[-3000:]
    # Every reader ran its cases.
    rows = [line.split() for line in p.stdout.splitlines()[1:]]
    assert sorted(r[0] for r in rows) == sorted(READERS.split(",")), p.stdout
    assert all(int(r[1]) == 12 for r in rows), p.stdout
