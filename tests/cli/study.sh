#!/usr/bin/env bash
# beltdyn study on a small loaded conveyor: 2 curves x 1 start time x 2
# delays = 4 cases, each a run directory; study.csv and study.json with one
# row per case and sane values; the table on stdout; `beltdyn report` on the
# study directory draws the start-curve comparison into plots/ and
# report.html. Bad options exit 2 with a message and write nothing.
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
model="$TEST_DATA/study_small.yaml"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BELTDYN" study "$model" -o "$work/st" --curves linear,s-curve --times 1 --delays 0,0.5 \
  --after 1 >"$work/out" 2>"$work/err" || { cat "$work/err" >&2; fail "study exited $?"; }
for c in linear_T1_d0 linear_T1_d0.5 s-curve_T1_d0 s-curve_T1_d0.5; do
  for f in summary.json history.csv tension.csv envelope.csv; do
    [ -s "$work/st/$c/$f" ] || fail "$c/$f missing"
  done
  grep -q "^$c " "$work/out" || fail "no table row for $c on stdout"
done
[ "$(wc -l <"$work/st/study.csv")" -eq 5 ] || fail "study.csv should have a header and 4 rows"
head -1 "$work/st/study.csv" | grep -q '^case,curve,start_time_s,delay_s,' || fail "study.csv header"
# every case completed; tight-side peak above the slack-side low; no slip;
# the run lasted delay + time + after
awk -F, 'NR > 1 {
  if ($6 != "completed") { print "case " $1 " status " $6; bad = 1 }
  if (!($7 > $9 && $9 > 0)) { print "case " $1 ": tight " $7 " slack " $9; bad = 1 }
  if (!($11 > 0 && $11 < $7)) { print "case " $1 ": swing " $11; bad = 1 }
  if ($16 != 0) { print "case " $1 " slipped"; bad = 1 }
  if (!($15 > 0)) { print "case " $1 ": no drive torque"; bad = 1 }
} END { exit bad }' "$work/st/study.csv" || fail "study.csv values"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert abs(d['duration_s'] - 2.5) < 0.01" "$work/st/linear_T1_d0.5/summary.json" || fail "duration not delay+time+after"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert len(d['cases'])==4" \
  "$work/st/study.json" || fail "study.json"

"$BELTDYN" report "$work/st" >"$work/out" 2>"$work/err" || { cat "$work/err" >&2; fail "report on a study"; }
for p in study_tension study_peaks; do
  for ext in png svg; do [ -s "$work/st/plots/$p.$ext" ] || fail "plots/$p.$ext missing"; done
done
grep -q 'data:image/png;base64,' "$work/st/report.html" || fail "no embedded images in report.html"
grep -q 'linear_T1_d0.5' "$work/st/report.html" || fail "report.html has no study table"

# bad options: exit 2, a message, no output directory
for args in "--curves bogus" "--times 0" "--delays x" "--after -1"; do
  set +e
  # shellcheck disable=SC2086
  "$BELTDYN" study "$model" -o "$work/bad" $args >"$work/out" 2>"$work/err"
  rc=$?
  set -e
  [ "$rc" -eq 2 ] || fail "'$args' gave exit $rc"
  [ -s "$work/err" ] || fail "'$args' gave no message"
  [ ! -e "$work/bad" ] || fail "'$args' wrote output"
done
set +e
"$BELTDYN" study "$TEST_DATA/bad_unknown_key.yaml" -o "$work/bad" >"$work/out" 2>"$work/err"
rc=$?
set -e
[ "$rc" -eq 2 ] && grep -qE ':[0-9]+:[0-9]+: error:' "$work/err" || fail "bad model: exit $rc"
echo PASS
