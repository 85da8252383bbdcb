#!/usr/bin/env bash
# beltdyn cases (cli.md) on a small loaded conveyor (tests/data/
# static_individual.yaml on the axial belt, rated 120 kN, a tight-side probe,
# 10 s; S-curve start of 4 s): five case directories with the run's
# outputs, cases.csv and cases.json with one completed row each, each case's
# report and DIR/report.html linking them. Physics each row must show:
# - a loaded start pulls harder than an empty one (peak belt tension higher);
# - the stop cases' records start at t_stop = 4 + max(2, 0.8) = 6 s, and the
#   run ends once the belt has stopped (head pulley at rest), before the
#   limit t_stop + 5·(the static stopping time in its setup) + 10 s;
# - braking stops the belt sooner than coasting and drops the slack side
#   further (lowest belt tension lower) — the brake pulls the belt back.
# The worst partial loading of a valley (tests/data/cases_valley.yaml): the
# slope in the 2000 m bottom curve runs from -10/300 rad linearly with arc
# length s/R, and passes -atan(0.02) = -0.019997 rad (f = 0.02) at
# (0.033320 - 0.019997)·2000 = 26.65 m into the curve; the curve begins
# hypot(300, 10) - 2000·tan(Δ/2) = 300.17 - 133.10 = 167.07 m along the
# carry, Δ = atan(0.1) + atan(1/30): the case loads from 193.7 m, within the
# 1.5 m the search samples the region at; and it pulls harder than the full
# loaded start (the decline's material helps the drive).
# Options of `study` are refused (exit 2, nothing written).
set -euo pipefail
. "$(dirname "$0")/lib/setup.sh"
model="$tmp/cases_small.yaml"
sed -e 's/^name: static individual/name: cases small/' \
    -e 's/^  axial_stiffness: 1.0e7/  axial_stiffness: 1.0e7\n  formulation: axial\n  rated_tension: 120e3/' \
    "$TEST_DATA/static_individual.yaml" >"$model"
printf 'simulation:\n  duration: 10\n  output_interval: 0.05\n  stabilize: true\n  probes:\n    - {name: tight, span: tail, at: 0.95}\n' >>"$model"
check() { local what=$1; shift; if "$@"; then ok "$what"; else bad "$what" "it did not hold"; fi; }
fail() { bad "$1" "stopped here"; tally; exit 1; }
out="$tmp/cases"

"$BELTDYN" cases "$model" -o "$out" -j 2 >"$tmp/out" 2>"$tmp/err" || { rc=$?; cat "$tmp/err" >&2; fail "cases exited $rc"; }
names="empty_start loaded_start loaded_coast_stop loaded_brake_stop partial_load_start"
for c in $names; do
  for f in summary.json history.csv envelope.csv report.html; do
    check "$c/$f written" test -s "$out/$c/$f"
  done
  check "a row for $c on stdout" grep -q "^$c " "$tmp/out"
done
check "cases.csv: header and 5 rows" test "$(wc -l <"$out/cases.csv")" -eq 6
check "cases.csv header" bash -c "head -1 '$out/cases.csv' | grep -q '^case,setup,records_from_s,status,'"
check "report.html links every case" bash -c "for c in $names; do grep -q \"href=\\\"\$c/report.html\\\"\" '$out/report.html' || exit 1; done"
check "report.html embeds its plot" grep -q 'data:image/png;base64,' "$out/report.html"
check "the physics of the cases" python3 - "$out" <<'PY'
import json, re, sys
d = sys.argv[1]
t = {c["case"]: c for c in json.load(open(d + "/cases.json"))["cases"]}
s = {c: json.load(open("%s/%s/summary.json" % (d, c))) for c in t}
bad = []
for c, row in t.items():
    if row["status"] != "completed": bad.append(c + " " + row["status"])
if not t["loaded_start"]["belt_tension_max_N"] > 1.05 * t["empty_start"]["belt_tension_max_N"]:
    bad.append("loaded start not above empty start")
for c in ("loaded_coast_stop", "loaded_brake_stop"):
    if abs(s[c].get("records_from_s", 0) - 6.0) > 0.01: bad.append(c + " records_from_s")
    if abs(t[c]["records_from_s"] - 6.0) > 0.01: bad.append(c + " table records_from_s")
    if abs(s[c]["pulleys"]["head"]["omega_final_rad_s"]) * 0.5 > 0.02: bad.append(c + " not at rest")
    window = float(re.search(r"(?:coast-down|braking) ~([0-9.e+]+) s", t[c]["setup"]).group(1))
    if not s[c]["duration_s"] < 6.0 + 5.0 * window + 10.0 - 1.0:
        bad.append(c + " ran to its limit instead of ending at rest")
if not s["loaded_brake_stop"]["duration_s"] < s["loaded_coast_stop"]["duration_s"]:
    bad.append("braking not sooner than coasting")
if not t["loaded_brake_stop"]["belt_tension_min_N"] < t["loaded_coast_stop"]["belt_tension_min_N"]:
    bad.append("braking did not drop the slack side below coasting's")
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY

"$BELTDYN" cases "$TEST_DATA/cases_valley.yaml" -o "$tmp/valley" -j 2 >"$tmp/out" 2>"$tmp/err" || { rc=$?; cat "$tmp/err" >&2; fail "cases on the valley exited $rc"; }
check "the valley's worst partial loading" python3 - "$tmp/valley" <<'PY'
import json, re, sys
t = {c["case"]: c for c in json.load(open(sys.argv[1] + "/cases.json"))["cases"]}
p = t["partial_load_start"]
m = re.search(r"loaded from ([0-9.]+) m past the feed point", p["setup"])
ok = m and abs(float(m.group(1)) - 193.7) <= 1.6
ok = ok and p["belt_tension_max_N"] > t["loaded_start"]["belt_tension_max_N"]
print(p["setup"], p["belt_tension_max_N"], t["loaded_start"]["belt_tension_max_N"])
sys.exit(0 if ok else 1)
PY

if "$BELTDYN" cases "$model" -o "$tmp/bad" --curves linear >"$tmp/out" 2>"$tmp/err"; then rc=0; else rc=$?; fi
check "cases --curves: exit 2" test "$rc" -eq 2
check "cases --curves: says why" grep -q "belong to study" "$tmp/err"
check "cases --curves: nothing written" test ! -e "$tmp/bad"
tally
