#!/usr/bin/env bash
# Installs what the build and the tests need, only when it is missing:
# Debian packages (needs root or sudo) and a Python venv (.venv) holding the
# test peers. Usage: scripts/install-deps.sh [--bench]
set -euo pipefail
repo_root=$(cd "$(dirname "$0")/.." && pwd)

debian_packages=(make gnat gprbuild libxmlada-dom12-dev libxmlada-sax12-dev
                 libaunit22-dev cyclonedds-dev cyclonedds-tools
                 python3 python3-venv graphviz iproute2
                 libgtkada22-dev fonts-dejavu-core xvfb x11-utils imagemagick
                 alire libfastrtps-dev g++ openssl libglpk-dev
                 libzstd-dev liblz4-dev zlib1g-dev libsqlite3-dev)
# libgtkada22-dev: sancta-view (GtkAda, Cairo); fonts-dejavu-core: its text;
# xvfb, x11-utils (xwininfo), imagemagick (import): its tests on a virtual display.
# alire: the Alire crates' test (scripts/alire-build.sh).
# libfastrtps-dev, g++: the Fast DDS test peer (tests/fastdds); openssl: the
# SROS2 keystores of rclada security and the secured tests.
# libglpk-dev: the branch-and-cut solver (Sancta.Allocation.GLPK).
# libzstd-dev, liblz4-dev, zlib1g-dev: MCAP chunk compression and CRCs (RCL.MCAP).
# libsqlite3-dev: rosbag2 sqlite3 bags (.db3, Humble's default) read by RCL.SQLite.
[ "${1:-}" = "--bench" ] && debian_packages+=(rt-tests)

missing=()
for p in "${debian_packages[@]}"; do
   dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
      || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
   echo "install-deps: installing Debian packages: ${missing[*]}"
   sudo_cmd=""
   [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
   $sudo_cmd apt-get update -qq
   DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}" >/dev/null
fi

venv="$repo_root/.venv"
stamp="$venv/.requirements-stamp"
wanted="$repo_root/tests/interop/requirements.txt"
if [ "${1:-}" = "--bench" ]; then
   wanted="$repo_root/bench/requirements.txt"
   stamp="$venv/.bench-requirements-stamp"
fi
if [ ! -x "$venv/bin/python" ]; then
   echo "install-deps: creating Python venv $venv"
   python3 -m venv "$venv"
fi
if [ ! -f "$stamp" ] || ! cmp -s "$wanted" "$stamp"; then
   echo "install-deps: installing Python packages from $wanted"
   "$venv/bin/pip" install -q --disable-pip-version-check -r "$wanted"
   cp "$wanted" "$stamp"
fi
