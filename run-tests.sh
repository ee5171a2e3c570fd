#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: core, filter, pvpython and
# command-line tests in ./build, then the core's unit tests again in
# ./build-asan with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh

jobs=$(nproc)
status=0
(cd build && ctest --output-on-failure -j "$jobs") || status=1

cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMP_CORE_ONLY=ON -DCMP_ENABLE_SANITIZERS=ON
cmake --build build-asan
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$jobs") || status=1

if [ "$status" -ne 0 ]; then
  echo "run-tests: FAILED"
else
  echo "run-tests: all tests passed"
fi
exit "$status"
