#!/usr/bin/env bash
# xvfb-run, run once more when the X server it started could not be reached.
#
# Each rendering test starts its own Xvfb with `xvfb-run -a`, and the tests
# take turns (RESOURCE_LOCK). Still, now and then a test aborts at its first
# render window with "bad X server connection" (seen right after another
# test's Xvfb on the same display number; xvfb-run stops its server without
# waiting for it to exit). That message means our code never ran, so running
# the test again is honest; any other failure is passed on as it is.
set -u
stderr_log=$(mktemp)
trap 'rm -f "$stderr_log"' EXIT
for attempt in 1 2; do
  xvfb-run "$@" 2>"$stderr_log"
  status=$?
  cat "$stderr_log" >&2
  if [ "$status" -eq 0 ] || ! grep -q "bad X server connection" "$stderr_log"; then
    exit "$status"
  fi
  if [ "$attempt" -eq 1 ]; then
    echo "xvfb-run-retry: the X server could not be reached; running again once" >&2
    sleep 2
  fi
done
exit "$status"
