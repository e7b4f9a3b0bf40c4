#!/usr/bin/env bash
# The cargo runner for wasm32-wasip1: Node.js's WASI (run.mjs). Node 20 has crashed (SIGSEGV,
# status 139) while tearing down after some simd128 test binaries had finished and reported;
# such a run passes only if the harness printed its complete "test result: ok." line first.
# Every other failure is a failure.
set -uo pipefail
log=$(mktemp)
node "$(dirname "$0")/run.mjs" "$@" | tee "$log"
rc=${PIPESTATUS[0]}
if [ "$rc" -eq 139 ] && grep -q '^test result: ok\. [0-9]* passed; 0 failed' "$log"; then
  echo "run.sh: node crashed in teardown after a complete passing run; accepted" >&2
  rc=0
fi
rm -f "$log"
exit "$rc"
