#!/usr/bin/env bash
# beltdyn report DIR of a boom run (summary.json "kind": "boom"): from the
# small run directory in tests/data/boom_run (no simulation), report.html
# names every figure and embeds it, each plots/NAME.png is a PNG, and the
# cards show the summary's figures; a run directory without beams.csv, or
# with a malformed beams.csv or history.csv, fails with exit 2 and a
# message naming the file.
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cp -r "$TEST_DATA/boom_run" "$work/run"
set +e
"$BELTDYN" report "$work/run" >"$work/out" 2>"$work/err"
rc=$?
set -e
[ "$rc" -eq 0 ] || { cat "$work/err" >&2; fail "beltdyn report exited $rc"; }
html="$work/run/report.html"
[ -s "$html" ] || fail "no report.html"

figures="boom_tip boom_cylinders boom_pads boom_moment boom_shape energy"
for p in $figures; do
  png="$work/run/plots/$p.png"
  [ -s "$png" ] || fail "plots/$p.png missing"
  [ -s "$work/run/plots/$p.svg" ] || fail "plots/$p.svg missing"
  sig="$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')"
  [ "$sig" = "89504e470d0a1a0a" ] || fail "plots/$p.png is not a PNG (starts $sig)"
  [ "$(stat -c %s "$png")" -gt 10000 ] || fail "plots/$p.png is too small to hold a plot"
  grep -q "<figure id=\"$p\">" "$html" || fail "report.html does not name the figure $p"
done
n="$(grep -o 'data:image/png;base64,' "$html" | wc -l)"
[ "$n" -eq 6 ] || fail "report.html embeds $n images, not 6"
grep -q 'beltdyn boom run' "$html" || fail "report.html does not say it is a boom run"
# the cards: summary.json's figures, the luffing one a moment (luffing_unit N*m)
for card in "tip deflection max" "telescopic cylinder force max" "luffing moment max" \
            "pad normal force max" "energy balance error" "status" "warnings"; do
  grep -q "<div class=k>$card</div>" "$html" || fail "no card '$card'"
done
grep -q '<div class=v>1.396 m</div>' "$html" || fail "tip deflection card is not 1.396 m"
grep -q '<div class=v>907.7 kN</div>' "$html" || fail "cylinder card is not 907.7 kN"
grep -q '<div class=v>4027 kN·m</div>' "$html" || fail "luffing card is not 4027 kN·m"
grep -q '<div class=v>1262 kN</div>' "$html" || fail "pad card is not 1262 kN"
grep -q 'luffing moment max \[N·m\]' "$html" || fail "summary table does not give the moment in N·m"
if grep -q 'src="http\|href="http' "$html"; then fail "report.html refers outside"; fi

# exit 2 and a message naming the file
expect_error() {   # NAME WHAT-IN-MESSAGE: run the report of $work/bad
  set +e
  "$BELTDYN" report "$work/bad" >"$work/out" 2>"$work/err"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || fail "$1: exit $code, not 2 ($(cat "$work/err"))"
  grep -q -- "$2" "$work/err" || fail "$1: the message does not say '$2': $(cat "$work/err")"
}
cp -r "$TEST_DATA/boom_run" "$work/bad"
rm "$work/bad/beams.csv"
expect_error "no beams.csv" "beams.csv"
rm -rf "$work/bad"

cp -r "$TEST_DATA/boom_run" "$work/bad"
# line 10 of beams.csv: section 0
awk -F, -v OFS=, 'NR == 10 { $2 = 0 } { print }' "$TEST_DATA/boom_run/beams.csv" \
  >"$work/bad/beams.csv"
expect_error "section 0" "beams.csv:10: section 0"
rm -rf "$work/bad"

cp -r "$TEST_DATA/boom_run" "$work/bad"
sed -i '1s/tip_rigid\.x_m/tip_rigid_x/' "$work/bad/history.csv"
expect_error "history without tip_rigid.x_m" "history.csv:1: no column 'tip_rigid.x_m'"
rm -rf "$work/bad"

cp -r "$TEST_DATA/boom_run" "$work/bad"
sed -i 's/"N\*m"/"kN"/' "$work/bad/summary.json"
expect_error "luffing_unit kN" "summary.json: boom.luffing_unit"
echo "PASS"
