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
# The ROS 2 library finds its bundled interfaces under $RCLADA_ROOT/share;
# SANCTA's sancta_msgs are on its path for the rclada CLI too.
export RCLADA_ROOT="$repo_root"
export RCLADA_INTERFACE_PATH="$repo_root/share/interfaces${RCLADA_INTERFACE_PATH:+:$RCLADA_INTERFACE_PATH}"
export PATH="$repo_root/bin:$PATH"
