#!/usr/bin/env bash
# Runs every benchmark script bench/bench-*.sh in turn (each prints its own
# table and writes CSV/JSON under out/bench/). Loopback only.
set -uo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
mkdir -p out/bench
status=0
for b in bench/bench-*.sh; do
   [ -e "$b" ] || continue
   echo "== $b"
   bash "$b" || { echo "bench: $b failed"; status=1; }
done
exit $status
