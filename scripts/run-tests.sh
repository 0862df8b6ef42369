#!/usr/bin/env bash
# Runs every test suite (the AUnit driver, then the pytest interoperability
# suites) on loopback with a domain id of this run's own, and ends with one
# line "N passed, N failed" summed over all suites. Exits non-zero when any
# test failed or a suite could not run.
set -uo pipefail
# On a shared development machine, full runs queue behind each other (runs in
# parallel on 2 cores make timing-sensitive suites fail); CI runs alone.
if [ "${CI:-}" != "true" ] && [ -z "${SANCTA_TESTS_LOCKED:-}" ] && command -v flock >/dev/null; then
   export SANCTA_TESTS_LOCKED=1
   echo "run-tests: waiting for /tmp/sancta-run-tests.lock (one full run at a time on this machine)"
   exec flock /tmp/sancta-run-tests.lock "$0" "$@"
fi
source "$(dirname "$0")/env.sh"
cd "$repo_root"

passed=0
failed=0
status=0
log_dir="$repo_root/obj/test-logs"
mkdir -p "$log_dir"

echo "== AUnit suites (ROS_DOMAIN_ID=$ROS_DOMAIN_ID, loopback only)"
# A test that fails may leave a task running, which keeps the driver from
# exiting: a time limit turns such a hang into a reported failure.
timeout -k 15 "${AUNIT_TIMEOUT:-1200}" ./bin/test_driver 2>&1 | tee "$log_dir/aunit.txt"
driver_status=${PIPESTATUS[0]}
if [ "$driver_status" -eq 124 ] || [ "$driver_status" -eq 137 ]; then
   echo "run-tests: the AUnit driver did not end within ${AUNIT_TIMEOUT:-1200} s (killed)"
   failed=$((failed + 1))
   status=1
fi
total=$(sed -n 's/^Total Tests Run: *\([0-9]*\).*/\1/p' "$log_dir/aunit.txt")
ok=$(sed -n 's/^Successful Tests: *\([0-9]*\).*/\1/p' "$log_dir/aunit.txt")
if [ -z "$total" ] || [ -z "$ok" ]; then
   echo "run-tests: the AUnit driver did not report its counts (exit $driver_status)"
   failed=$((failed + 1))
   status=1
else
   passed=$((passed + ok))
   failed=$((failed + total - ok))
   [ "$driver_status" -ne 0 ] && status=1
fi

if [ -d tests/interop ] && ls tests/interop/test_*.py >/dev/null 2>&1; then
   echo "== pytest interoperability suites"
   .venv/bin/python -m pytest -q -p no:cacheprovider tests/interop 2>&1 \
      | tee "$log_dir/pytest.txt"
   py_status=${PIPESTATUS[0]}
   summary=$(grep -E '^=*.*[0-9]+ (passed|failed|error)' "$log_dir/pytest.txt" | tail -1)
   py_passed=$(echo "$summary" | grep -oE '[0-9]+ passed' | grep -oE '[0-9]+' || true)
   py_failed=$(echo "$summary" | grep -oE '[0-9]+ failed' | grep -oE '[0-9]+' || true)
   py_errors=$(echo "$summary" | grep -oE '[0-9]+ errors?' | grep -oE '[0-9]+' || true)
   passed=$((passed + ${py_passed:-0}))
   failed=$((failed + ${py_failed:-0} + ${py_errors:-0}))
   # pytest exit 5 = no tests collected: not a failure of its own.
   if [ "$py_status" -ne 0 ] && [ "$py_status" -ne 5 ]; then
      status=1
      if [ -z "$summary" ]; then
         echo "run-tests: pytest ended with status $py_status and no summary"
         failed=$((failed + 1))
      fi
   fi
fi

# The Alire crates (ros2/, sancta/) with Debian's alr, offline: one test each.
echo "== Alire crates (alr build, offline, repository index)"
scripts/alire-build.sh 2>&1 | tee "$log_dir/alire.txt"
alire_passed=$(grep -c '^alire: PASS' "$log_dir/alire.txt")
alire_failed=$(grep -c '^alire: FAIL' "$log_dir/alire.txt")
passed=$((passed + alire_passed))
failed=$((failed + alire_failed))
if [ "$alire_passed" -eq 0 ] && [ "$alire_failed" -eq 0 ]; then
   failed=$((failed + 1))
fi

[ "$failed" -gt 0 ] && status=1
echo "$passed passed, $failed failed"
exit $status
