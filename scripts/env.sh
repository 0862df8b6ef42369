# Sourced by the scripts: the loopback-only DDS configuration and a domain id
# of this run's own, so that parallel runs on one machine never cross.
# Nothing here sends traffic anywhere but 127.0.0.1.
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export CYCLONEDDS_URI="file://$repo_root/share/cyclonedds-localhost.xml"
export ROS_LOCALHOST_ONLY=1
export ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
if [ -z "${ROS_DOMAIN_ID:-}" ]; then
   # A domain id in 1..200 that no other run on this machine holds: each run
   # keeps an flock on $TMPDIR/rclada-domain-locks/<id>.lock open for its
   # lifetime (its children inherit the descriptor, so the lock lasts until
   # the last of them exits); the search starts at a place drawn from the pid
   # and the clock. tests/interop/conftest.py and tests/src/test_driver.adb
   # take the same locks when run without this file.
   rclada_domain_locks="${TMPDIR:-/tmp}/rclada-domain-locks"
   mkdir -p "$rclada_domain_locks" 2>/dev/null && chmod 1777 "$rclada_domain_locks" 2>/dev/null
   rclada_domain_start=$(( ( $$ + $(date +%s) ) % 200 ))
   for rclada_domain_step in $(seq 0 199); do
      rclada_domain=$(( ( rclada_domain_start + rclada_domain_step ) % 200 + 1 ))
      if exec {rclada_domain_fd}>>"$rclada_domain_locks/$rclada_domain.lock" 2>/dev/null; then
         if flock -n "$rclada_domain_fd"; then
            export ROS_DOMAIN_ID=$rclada_domain
            break
         fi
         exec {rclada_domain_fd}>&-
      fi
   done
   if [ -z "${ROS_DOMAIN_ID:-}" ]; then
      # No lock could be taken (no flock, read-only /tmp, 200 runs at once).
      export ROS_DOMAIN_ID=$(( rclada_domain_start + 1 ))
   fi
   unset rclada_domain_locks rclada_domain_start rclada_domain_step rclada_domain
fi
export SANCTA_ROOT="$repo_root"
# The ROS 2 library finds its bundled interfaces under $RCLADA_ROOT/share;
# SANCTA's sancta_msgs are on its path for the rclada CLI too.
export RCLADA_ROOT="$repo_root"
export RCLADA_INTERFACE_PATH="$repo_root/share/interfaces${RCLADA_INTERFACE_PATH:+:$RCLADA_INTERFACE_PATH}"
export PATH="$repo_root/bin:$PATH"
