#!/usr/bin/env bash
# The main job on its embedded default. Until the team mission exists this
# runs the most complete end-to-end example available.
set -euo pipefail
source "$(dirname "$0")/env.sh"
cd "$repo_root"
echo "demo: nothing end-to-end is built yet; running the test driver instead"
./bin/test_driver
