#!/usr/bin/env bash
# Several hosts: each team node in its own network namespace.
#
# Creates a hub namespace holding a bridge and one namespace per node
# (operator + 3 robots), each linked to the bridge by a veth pair, with
# addresses in 10.213.77.0/24 that exist ONLY inside these namespaces
# (nothing is configured on the host). Each node's Cyclone DDS
# configuration names its own namespace's address and its peers' addresses
# (unicast discovery, no multicast). The test shows discovery (a round
# with the 3 robots), allocation, then cuts robot r3's link at the bridge
# and shows the re-allocation among the survivors (a round without r3) and
# the mission finished by them. The namespaces are removed on exit, also on
# failure. Needs root (CAP_NET_ADMIN): otherwise exits 77 (skipped) with
# the reason.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo_root="$(cd "$here/../.." && pwd)"
sancta="$repo_root/bin/sancta"
mission="$repo_root/share/missions/office-team.xml"
prefix="sancta_t$$"
hub="${prefix}_hub"
nodes=(operator r1 r2 r3)
work="$(mktemp -d)"
echo "logs: $work"

skip() { echo "SKIP: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "needs root to create network namespaces"
command -v ip >/dev/null || skip "the ip command (iproute2) is missing"
[ -x "$sancta" ] || { echo "FAIL: $sancta is not built"; exit 1; }

cleanup() {
   for pid in $(jobs -p); do kill "$pid" 2>/dev/null; done
   sleep 1
   for pid in $(jobs -p); do kill -9 "$pid" 2>/dev/null; done
   wait 2>/dev/null
   for i in "${!nodes[@]}"; do ip netns del "${prefix}_$i" 2>/dev/null; done
   ip netns del "$hub" 2>/dev/null
   rm -rf "$work"
}
trap cleanup EXIT

ip netns add "$hub" 2>/dev/null || skip "creating a network namespace is not permitted here"
probe=$(ip netns exec "$hub" true 2>&1) \
   || skip "running a program in a network namespace is not possible here: $probe"
ip -n "$hub" link add br0 type bridge || exit 1
ip -n "$hub" link set br0 up
ip -n "$hub" link set lo up
peers=""
for i in "${!nodes[@]}"; do peers="$peers<Peer address=\"10.213.77.$((i + 1))\"/>"; done
for i in "${!nodes[@]}"; do
   ns="${prefix}_$i"
   addr="10.213.77.$((i + 1))"
   ip netns add "$ns" || exit 1
   # The veth pair is created inside the hub namespace, one end moved to ns.
   ip -n "$hub" link add "h$i" type veth peer name "n$i" || exit 1
   ip -n "$hub" link set "n$i" netns "$ns" || exit 1
   ip -n "$hub" link set "h$i" master br0
   ip -n "$hub" link set "h$i" up
   ip -n "$ns" link set lo up
   ip -n "$ns" link set "n$i" name eth0
   ip -n "$ns" addr add "$addr/24" dev eth0
   ip -n "$ns" link set eth0 up
   cat > "$work/cyclone-$i.xml" <<XML
<CycloneDDS>
  <Domain Id="any">
    <General>
      <Interfaces><NetworkInterface address="$addr"/></Interfaces>
      <AllowMulticast>false</AllowMulticast>
    </General>
    <Discovery>
      <ParticipantIndex>auto</ParticipantIndex>
      <MaxAutoParticipantIndex>20</MaxAutoParticipantIndex>
      <Peers>$peers</Peers>
    </Discovery>
  </Domain>
</CycloneDDS>
XML
done

run_in() {  # run_in INDEX LOG ARGS...
   local i=$1 log=$2; shift 2
   ip netns exec "${prefix}_$i" env CYCLONEDDS_URI="file://$work/cyclone-$i.xml" \
      ROS_DOMAIN_ID=42 SANCTA_ROOT="$repo_root" "$sancta" team-agent "$@" > "$log" 2>&1 &
}

for i in 1 2 3; do
   run_in "$i" "$work/r$i.log" --id "r$i" --x $((i * 3)) --y 10 --rate 4 --lease 1.0 --for 150
done
run_in 0 "$work/operator.log" --operator "$mission" --lease 1.0 --for 150
op_pid=$!

wait_for() {  # wait_for SECONDS PATTERN FILE
   local t=0
   while ! grep -qE "$2" "$3" 2>/dev/null; do
      sleep 0.2; t=$((t + 1))
      if [ "$t" -ge $(($1 * 5)) ]; then return 1; fi
   done
   return 0
}

fail() {
   echo "FAIL: $*"
   for f in "$work"/*.log; do echo "--- $(basename "$f")"; tail -15 "$f"; done
   exit 1
}

wait_for 60 "round [0-9]+ robots r1,r2,r3 " "$work/operator.log" \
   || fail "no round with the three robots (discovery across namespaces)"
echo "ok: discovery and allocation across namespaces: $(grep -m1 'robots r1,r2,r3' "$work/operator.log")"
wait_for 60 "progress ([3-9]|[1-9][0-9])/" "$work/operator.log" || fail "no progress"
wait_for 60 "r3: did" "$work/r3.log" || fail "r3 did no task"
ip -n "$hub" link set h3 down   # r3's host is cut off
echo "ok: r3's link cut at the bridge after $(grep -c 'did' "$work/r3.log") of its tasks"
wait_for 60 "round [0-9]+ robots r1,r2 " "$work/operator.log" \
   || fail "no re-allocation without r3"
echo "ok: re-allocation among the survivors: $(grep 'robots r1,r2 ' "$work/operator.log" | tail -1)"
wait "$op_pid"
status=$?
[ "$status" -eq 0 ] || fail "the operator did not see every task done (status $status)"
grep -q "operator: all done" "$work/operator.log" || fail "no 'all done'"
# Every task once, and none by r3 after the cut as seen by the team.
tasks=$(grep -c '^done ' "$work/operator.log")
by_r3=$(grep -c ' by r3$' "$work/operator.log")
[ "$tasks" -eq "$(grep -c '<\(goto\|explore\|choose\) ' "$mission")" ] || fail "not every task listed once"
[ "$by_r3" -ge 1 ] || fail "the tasks r3 did before the cut were not kept"
echo "ok: mission finished by the survivors: $tasks tasks, $by_r3 kept from r3 (done before the cut)"
echo "PASS"
