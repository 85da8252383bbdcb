#!/usr/bin/env bash
# beltdyn report DIR through the command: a fake run gives plots and
# report.html (exit 0); a missing DIR gives exit 2 and a message. Skipped
# (exit 0) while the command does not have the report subcommand yet.
set -euo pipefail
helper="$(dirname "$BELTDYN")/tests/test_report"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$helper" fake "$work/run" 120 60

set +e
"$BELTDYN" report "$work/run" >"$work/out" 2>"$work/err"
rc=$?
set -e
if [ "$rc" -ne 0 ] && grep -qiE "unknown|usage|subcommand|command" "$work/err" && \
   [ ! -f "$work/run/report.html" ]; then
  echo "SKIP: beltdyn has no report subcommand yet ($(head -1 "$work/err"))"
  exit 0
fi
if [ "$rc" -ne 0 ]; then
  echo "FAIL: beltdyn report exited $rc" >&2
  cat "$work/err" >&2
  exit 1
fi
for p in tension_surface envelope probes drives takeups energy; do
  for ext in png svg; do
    if [ ! -s "$work/run/plots/$p.$ext" ]; then
      echo "FAIL: plots/$p.$ext missing" >&2
      exit 1
    fi
  done
done
grep -q 'data:image/png;base64,' "$work/run/report.html" || { echo "FAIL: no embedded images" >&2; exit 1; }
grep -q 'CV-01 overland' "$work/run/report.html" || { echo "FAIL: no model name" >&2; exit 1; }

# a missing directory: exit 2 with a message naming it
set +e
"$BELTDYN" report "$work/nope" >"$work/out" 2>"$work/err"
rc=$?
set -e
if [ "$rc" -ne 2 ] || ! grep -q "nope" "$work/err"; then
  echo "FAIL: missing DIR gave exit $rc, message: $(cat "$work/err")" >&2
  exit 1
fi
echo "PASS"
