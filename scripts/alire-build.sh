#!/usr/bin/env bash
# Builds the Alire crates of the repository with Debian's alr (1.2.1),
# offline: a throw-away alr configuration (its own HOME) that knows only the
# repository's index share/alire-index, where Cyclone DDS, XML/Ada and AUnit
# are system externals (Debian packages). One line per crate:
#   alire: PASS rclada (ros2/)      or      alire: FAIL sancta (sancta/) ...
# and the last line "alire: N passed, N failed". Exits non-zero on a failure.
# The crates build in the repository's own object folders (debug mode), so
# after "make build" alr finds them up to date.
set -uo pipefail
repo_root=$(cd "$(dirname "$0")/.." && pwd)
if ! command -v alr >/dev/null 2>&1; then
   echo "alire: FAIL alr not found (Debian package alire)"
   echo "alire: 0 passed, 1 failed"
   exit 1
fi
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
export HOME="$home" XDG_CONFIG_HOME="$home/.config"
log="$repo_root/obj/test-logs"
mkdir -p "$log"
alr() { command alr -n "$@"; }
alr config --global --set index.auto_community false
alr config --global --set toolchain.assistant false
alr index --add="$repo_root/share/alire-index" --name=sancta_local >/dev/null
passed=0
failed=0
for crate in ros2 sancta; do
   name=$(sed -n 's/^name = "\(.*\)"/\1/p' "$repo_root/$crate/alire.toml")
   if (cd "$repo_root/$crate" && timeout 900 alr build) > "$log/alire-$name.txt" 2>&1; then
      echo "alire: PASS $name ($crate/)"
      passed=$((passed + 1))
   else
      echo "alire: FAIL $name ($crate/): see $log/alire-$name.txt"
      tail -5 "$log/alire-$name.txt"
      failed=$((failed + 1))
   fi
done
echo "alire: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
