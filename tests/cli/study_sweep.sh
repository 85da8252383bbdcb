#!/usr/bin/env bash
# `beltdyn study --vary` and `--sample` (issue 16) on a small conveyor whose
# answers are known (tests/data/sweep_small.yaml, starts of 1-3 s in a 4 s
# run):
# - a grid over the drive's start time (1, 2, 3 s), the takeup's
#   counterweight (600, 900 kg) and design.f (not in the file, and not used
#   by a simulation): 12 cases in grid order with a column per key; the
#   peak tight-side tension falls as the start time grows (the start's
#   acceleration falls), the lowest slack-side tension rises with the
#   counterweight; the report ranks the counterweight first for the lowest
#   tension (rho > 0.8), gives the start time a negative rho with the peak
#   tension and design.f rho 0 and the last rank everywhere;
# - --best tight_tension_max_N --where slipped=false picks the 3 s start;
# - a case that cannot be built is reported in the table, the others run;
# - a Latin hypercube is the same for a seed, another for another seed,
#   and puts one case in each stratum of each key;
# - bad keys and ranges exit 2 with a message naming the key, and write
#   nothing.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/lib/tally.sh"
model="$DATA/sweep_small.yaml"
T=pulleys.head.drive.start.time
M=pulleys.tail.takeup.mass

if "$BELTDYN" study "$model" -o "$work/g" --vary "$T=1:3:3" --vary "$M=600:900:2" \
    --vary design.f=0.01:0.03:2 --best tight_tension_max_N --where slipped=false -j 2 \
    >"$work/g.out" 2>&1; then
    ok "grid sweep completed"
else
    bad "grid sweep" "exit $?: $(tail -3 "$work/g.out")"
fi
if python3 - "$work/g/study.csv" "$T" "$M" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
T, M = sys.argv[2], sys.argv[3]
head = open(sys.argv[1]).readline().strip().split(",")
assert head[:4] == ["case", T, M, "design.f"], head[:4]
assert len(rows) == 12, len(rows)
# grid order: the first key slowest
want = [(t, m, f) for t in ("1", "2", "3") for m in ("600", "900") for f in ("0.01", "0.03")]
got = [(r[T], r[M], r["design.f"]) for r in rows]
assert got == want, got
assert all(r["status"] == "completed" for r in rows)
by = {(r[T], r[M], r["design.f"]): r for r in rows}
for m in ("600", "900"):
    for f in ("0.01", "0.03"):
        peak = [float(by[(t, m, f)]["tight_tension_max_N"]) for t in ("1", "2", "3")]
        assert peak[0] > peak[1] > peak[2], ("peak tension should fall with start time", m, f, peak)
for t in ("1", "2", "3"):
    for f in ("0.01", "0.03"):
        lo = [float(by[(t, m, f)]["slack_tension_min_N"]) for m in ("600", "900")]
        assert lo[1] > lo[0], ("lowest tension should rise with the counterweight", t, lo)
        # design.f changes nothing a run computes
        a, b = by[(t, "600", "0.01")], by[(t, "600", "0.03")]
        assert a["tight_tension_max_N"] == b["tight_tension_max_N"]
PY
then ok "grid table: keys in columns, peak tension falls with start time, lowest rises with counterweight"
else bad "grid table" "see above"; fi
if grep -q "^best (lowest tight_tension_max_N where slipped=false): case_.*$T = 3," "$work/g.out" \
    && python3 -c "import json,sys; b=json.load(open(sys.argv[1]))['best']; assert b['case'].startswith('case_')" "$work/g/study.json"
then ok "--best picks a 3 s start, recorded in study.json"
else bad "--best" "$(grep best "$work/g.out")"; fi

if "$BELTDYN" report "$work/g" >"$work/rep.out" 2>&1; then ok "report on the sweep"
else bad "report" "$(tail -3 "$work/rep.out")"; fi
if python3 - "$work/g" "$T" "$M" <<'PY'
import csv, sys
d, T, M = sys.argv[1:]
rank = {}
for r in csv.DictReader(open(d + "/sensitivity.csv")):
    rank.setdefault(r["output"], []).append((r["key"], float(r["spearman_rho"])))
low = rank["slack_tension_min_N"]
assert low[0][0] == M and low[0][1] > 0.8, low
peak = dict(rank["tight_tension_max_N"])
assert peak[T] < 0, peak
for out, keys in rank.items():
    assert keys[-1][0] == "design.f" and abs(keys[-1][1]) < 1e-9, (out, keys)
html = open(d + "/report.html").read()
assert "Which key matters" in html and T in html
PY
then ok "sensitivity: counterweight first for the lowest tension, start time against the peak, design.f last at 0"
else bad "sensitivity" "$(cat "$work/g/sensitivity.csv")"; fi
for p in sensitivity sweep_k1 sweep_more_k3; do
    [ -s "$work/g/plots/$p.png" ] && [ -s "$work/g/plots/$p.svg" ] || bad "plots" "$p missing"
done

# Latin hypercube: one seed twice, another once
# (the shorter study_small.yaml: only the cases' keys are checked)
lhs=(--sample 5 --range "$T=1:3" --range "$M=600:900")
"$BELTDYN" study "$DATA/study_small.yaml" -o "$work/s1" "${lhs[@]}" --seed 7 -j 2 >"$work/s1.out" 2>&1
r1=$?
"$BELTDYN" study "$DATA/study_small.yaml" -o "$work/s2" "${lhs[@]}" --seed 7 -j 1 >"$work/s2.out" 2>&1
r2=$?
"$BELTDYN" study "$DATA/study_small.yaml" -o "$work/s3" "${lhs[@]}" --seed 8 -j 2 >"$work/s3.out" 2>&1
r3=$?
if [ $r1 -eq 0 ] && [ $r2 -eq 0 ] && [ $r3 -eq 0 ] && python3 - "$work" "$T" "$M" <<'PY'
import csv, sys
w, T, M = sys.argv[1:]
def keys(d):
    return [(r[T], r[M]) for r in csv.DictReader(open(w + "/" + d + "/study.csv"))]
a, b, c = keys("s1"), keys("s2"), keys("s3")
assert a == b and a != c, (a, b, c)
for k, (lo, hi) in ((0, (1.0, 3.0)), (1, (600.0, 900.0))):
    strata = sorted(int((float(x[k]) - lo) / (hi - lo) * 5) for x in a)
    assert strata == [0, 1, 2, 3, 4], strata
PY
then ok "Latin hypercube: same for a seed, one case per stratum"
else bad "Latin hypercube" "exit $r1 $r2 $r3: $(tail -2 "$work/s1.out")"; fi

# a case that fails (its time step above the stable one: its model loads,
# its build refuses it) is in the table; the other case completes; exit 1
"$BELTDYN" study "$DATA/study_small.yaml" -o "$work/f" --vary simulation.time_step=0.0001:0.01:2 \
    -j 2 >"$work/f.out" 2>"$work/f.err"
rc=$?
if [ $rc -eq 1 ] && grep -q "case_002.*time_step" "$work/f.err" \
    && grep -q "^case_001,0.0001,completed," "$work/f/study.csv" \
    && grep -q "^case_002,0.01,bad input," "$work/f/study.csv" \
    && python3 - "$work/f" <<'PY'
import csv, json, sys
rows = {r["case"]: r for r in csv.DictReader(open(sys.argv[1] + "/study.csv"))}
cases = {c["case"]: c for c in json.load(open(sys.argv[1] + "/study.json"))["cases"]}
# the failed case says why in the table (quoted CSV, the same text in the
# JSON); the completed one has an empty message
assert "time_step" in rows["case_002"]["message"], rows["case_002"]
assert cases["case_002"]["message"] == rows["case_002"]["message"]
assert rows["case_001"]["message"] == "" and cases["case_001"]["message"] == ""
PY
then
    ok "a failed case is in the table with its message, the other completes, exit 1"
else
    bad "failed case" "exit $rc: $(cat "$work/f/study.csv" "$work/f.err" 2>&1 | head -c 600)"
fi

# bad keys: exit 2, a message naming the key, nothing written
n=0
for spec in "pulleys.middle.mass=1:2:2|middle" "pulleys.head.wrap=1:2:2|pulleys.head.wrap" \
            "belt.colour=1:2:2|colour" "belt.mass_per_length=-1:2:2|belt.mass_per_length" \
            "belt=1:2:2|belt" "pulleys.head.drive.speed=1:2|expected" "nokey|expected"; do
    arg=${spec%|*} want=${spec#*|}
    n=$((n + 1))
    "$BELTDYN" study "$model" -o "$work/bad$n" --vary "$arg" >"$work/bad.out" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -q -- "$want" "$work/bad.out" && [ ! -e "$work/bad$n" ]; then
        ok "--vary $arg: exit 2 naming $want"
    else
        bad "--vary $arg" "exit $rc, output: $(head -c 400 "$work/bad.out")"
    fi
done
# one number under two spellings (by name and by index): exit 2 naming
# both keys, nothing written (it crashed, or ran a garbled model text)
for pair in "pulleys.head.radius pulleys.0.radius 0.2:0.25:2" \
            "idlers[0].spacing idlers.0.spacing 1:1.5:2"; do
    set -- $pair
    "$BELTDYN" study "$model" -o "$work/bad_same" --vary "$1=$3" --vary "$2=$3" \
        >"$work/bad.out" 2>&1
    rc=$?
    if [ $rc -eq 2 ] && grep -qF -- "$1" "$work/bad.out" && grep -qF -- "$2" "$work/bad.out" \
        && grep -q "same number" "$work/bad.out" && [ ! -e "$work/bad_same" ]; then
        ok "--vary $1 and $2: exit 2 naming both"
    else
        bad "--vary $1 and $2" "exit $rc, output: $(head -c 400 "$work/bad.out")"
    fi
done
"$BELTDYN" study "$model" -o "$work/bad_best" --vary "$T=1:2:2" --best nosuch >"$work/bad.out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q "nosuch" "$work/bad.out"; then ok "--best of no column: exit 2"
else bad "--best nosuch" "exit $rc"; fi
tally
