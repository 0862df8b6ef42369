#!/usr/bin/env bash
# Task allocation quality against OR-tools (see bench/allocation --help).
# Extra arguments are passed on, e.g. bench/bench-allocation.sh --time 3 --seeds 1
set -euo pipefail
source "$(dirname "$0")/../scripts/env.sh"
cd "$repo_root"
exec .venv/bin/python bench/allocation "$@"
