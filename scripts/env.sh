# Sourced by the scripts: the loopback-only DDS configuration and a domain id
# of this run's own, so that parallel runs on one machine never cross.
# Nothing here sends traffic anywhere but 127.0.0.1.
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export CYCLONEDDS_URI="file://$repo_root/share/cyclonedds-localhost.xml"
export ROS_LOCALHOST_ONLY=1
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
if [ -z "${ROS_DOMAIN_ID:-}" ]; then
   # 1..200, from this shell's pid and the clock.
   export ROS_DOMAIN_ID=$(( ( $$ + $(date +%s) ) % 200 + 1 ))
fi
export SANCTA_ROOT="$repo_root"
export PATH="$repo_root/bin:$PATH"
