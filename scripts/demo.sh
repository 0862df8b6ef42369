#!/usr/bin/env bash
# The main job on its embedded default: a team of four robots (each a team
# agent with its own DDS node) in the bundled office world runs a 24-task
# mission; one robot is killed mid-mission; the survivors re-plan and
# finish. Report under out/demo/. Extra arguments go to "sancta team"
# (e.g. --method auctions, --rate 50, --no-kill).
set -euo pipefail
source "$(dirname "$0")/env.sh"
cd "$repo_root"
exec ./bin/sancta team share/missions/office-team.xml --out out/demo "$@"
