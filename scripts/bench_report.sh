#!/usr/bin/env bash
# Time `beltdyn report` on a large fake run: NELEM elements x NTIMES output
# times in tension.csv (default 5000 x 1000, about 230 MB). The fake run is
# written by the test_report helper (tests/unit/test_report.c), so this
# does not need the simulator.
#   scripts/bench_report.sh [BUILD_DIR] [NELEM] [NTIMES]
set -euo pipefail
build="${1:-build}"
nelem="${2:-5000}"
ntimes="${3:-1000}"
helper="$build/tests/test_report"
if [ ! -x "$helper" ]; then
  echo "bench_report: $helper not built (cmake --build $build)" >&2
  exit 2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
echo "writing a fake run: $nelem elements x $ntimes output times" >&2
"$helper" fake "$work/run" "$nelem" "$ntimes"
ls -l "$work/run/tension.csv" >&2
start=$(date +%s.%N)
if [ -x "$build/beltdyn" ] && "$build/beltdyn" report "$work/run" 2>/dev/null; then
  how="beltdyn report"
else
  "$helper" report "$work/run" >/dev/null
  how="bd_report_write"
fi
end=$(date +%s.%N)
awk -v a="$start" -v b="$end" -v how="$how" -v n="$nelem x $ntimes" 'BEGIN { printf "%s: %.2f s for %s\n", how, b - a, n }'
