#!/usr/bin/env bash
# Bootstrap for a fresh Debian machine: installs make if it is missing, then
# runs "make TARGET...". Usage: ./make.sh run | ./make.sh test | ./make.sh bench
set -euo pipefail
cd "$(dirname "$0")"
if ! command -v make >/dev/null 2>&1; then
   sudo_cmd=""
   [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
   $sudo_cmd apt-get update -qq
   DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq make >/dev/null
fi
exec make --no-print-directory "$@"
