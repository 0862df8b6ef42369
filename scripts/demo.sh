#!/usr/bin/env bash
# The main job (make run): the team demo with every robot a SANCTA agent of
# one configuration file. "sancta demo" starts sancta-sim (bundled office
# world) and one "sancta run share/config/sim-team.xml --agent ID" process
# per agent (four robots r1..r4 and the operator, which publishes the
# 24-task mission); when a quarter of the tasks are done it kills one
# robot's agent process (and the robot in the simulator); the survivors
# re-plan and finish. Progress lines while it runs, a summary at the end,
# the report and every process's log under out/demo/. Extra arguments go to
# "sancta demo" (e.g. --set method=auctions, --rate 8, --no-kill, --check).
# The in-process variant of the same mission: bin/sancta team (sancta team --help).
set -euo pipefail
source "$(dirname "$0")/env.sh"
cd "$repo_root"
exec ./bin/sancta demo share/config/sim-team.xml --out out/demo "$@"
