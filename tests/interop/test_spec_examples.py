"""The code examples in the ROS 2 library's specs compile (issue 13, item 7).

Every block marked "Example:" in ros2/**/*.ads is extracted by
tests/spec_examples/extract.py into an Ada unit (with the names it uses
but does not declare from tests/spec_examples/contexts/) and compiled for
a semantic check with gprbuild -gnatc. A code-like block without the
marker (a line of Ada statements) is an error too, so that no example escapes
the check. Errors are reported at the spec's line."""
import os
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
EXTRACT = REPO / "tests" / "spec_examples" / "extract.py"
sys.path.insert(0, str(EXTRACT.parent))
import extract  # noqa: E402  (the block scanner the extraction uses)
GPR = REPO / "tests" / "spec_examples" / "spec_examples.gpr"
ADA_STATEMENT = re.compile(r"(:=.*|\)|^\s*end\b.*|^\s*[\w.]+(\s*\(.*\))?)\s*;\s*$")
# A line of Ada: an assignment, a call, an end; not prose ending in ";".


def specs():
    return sorted(str(p.relative_to(REPO)) for p in (REPO / "ros2").rglob("*.ads"))


def extract_and_compile(out, obj, spec_files, extra_sources=()):
    run = subprocess.run([sys.executable, str(EXTRACT), str(out)] + spec_files,
                         cwd=REPO, capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    for source in extra_sources:
        (out / source.name).write_text(source.read_text())
    env = dict(os.environ, SPEC_EXAMPLES_DIR=str(out), SPEC_EXAMPLES_OBJ=str(obj))
    build = subprocess.run(["gprbuild", "-q", "-p", "-P", str(GPR), "-c", "-u", "-k",
                            "-j2"], cwd=REPO, env=env, capture_output=True, text=True,
                           timeout=600)
    index = {}
    for line in (out / "examples.txt").read_text().splitlines():
        if line.strip():
            unit, where, lines = (line.split() + [""])[:3]
            spec = where.rsplit(":", 1)[0]
            index[unit] = (spec, dict(pair.split("=") for pair in lines.split(",") if pair))

    def at_spec_line(m):
        spec, lines = index.get(m.group(1), (None, {}))
        if spec is None:
            return m.group(0)
        return "%s:%s (%s)" % (spec, lines.get(m.group(2), "?"), m.group(0))

    errors = [re.sub(r"^([\w-]+)\.adb:(\d+)", at_spec_line, line)
              for line in (build.stdout + build.stderr).splitlines()
              if re.search(r": (error|warning):", line) or "not found" in line]
    return run.stdout, build.returncode, errors, index


def test_every_marked_example_of_the_ros2_specs_compiles(tmp_path):
    summary, status, errors, index = extract_and_compile(
        tmp_path / "src", tmp_path / "obj", specs())
    assert len(index) >= 50, summary
    assert status == 0 and not errors, "\n".join(errors[:60])


def test_code_blocks_are_marked_as_examples():
    unmarked = []
    for spec in specs():
        for first, marked, body in extract.code_blocks((REPO / spec).read_text().split("\n")):
            if not marked and any(ADA_STATEMENT.search(code.split("--")[0]) for _, code in body):
                unmarked.append("%s:%d" % (spec, first))
    assert not unmarked, "Ada code blocks without \"Example:\": " + ", ".join(unmarked)


def test_a_wrong_example_is_reported_at_its_spec_line(tmp_path):
    spec = tmp_path / "rcl-wrong_example.ads"
    spec.write_text("--  A unit whose example is wrong.\n"
                    "--  Example:\n"
                    "--     Count : Integer := \"three\";\n"
                    "package RCL.Wrong_Example is\n"
                    "end RCL.Wrong_Example;\n")
    _, status, errors, _ = extract_and_compile(tmp_path / "src", tmp_path / "obj",
                                               [str(spec)], extra_sources=[spec])
    assert status != 0
    assert any(e.startswith(str(spec) + ":3 (") and "expected type" in e for e in errors), errors
