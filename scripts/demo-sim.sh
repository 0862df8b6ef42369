#!/usr/bin/env bash
# The configuration-file demo (scripts/demo.sh) with its options from the
# environment, for trying the combinations: METHOD (annealer|auctions),
# RATE (default 2), SIM_TIME (1: the agents on /clock, default; 0: on the
# wall clock). Logs and report under out/demo-sim/. Extra arguments go to
# "sancta demo".
set -uo pipefail
source "$(dirname "$0")/env.sh"
cd "$repo_root"
clock=$([ "${SIM_TIME:-1}" = 1 ] || echo --wall-clock)
exec ./bin/sancta demo share/config/sim-team.xml --set "method=${METHOD:-annealer}" \
   --rate "${RATE:-2}" $clock --out out/demo-sim --check "$@"
