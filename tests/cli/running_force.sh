#!/usr/bin/env bash
# Every run holds its steady running force to the model's own resistance
# law (sensors/running.c; issue 10's invariant), and says so in
# summary.json ("running_force"), in the checks table and, when it fails,
# in a warning.
#
# The model is the minimal loop of docs/physics.md §10
# (tests/data/idler_turn_loop.yaml): level, empty, two
# 0.3 m pulleys 30 m apart at 6 m/s and 5000 N, carry idlers every 1.2 m,
# return idlers every 3 m, rolling resistance 0.01, nothing else that
# takes energy. Its law by hand: each idler carries the belt between the
# midpoints to its neighbours, the pulleys' tangent points being the
# first and last neighbours, so the idlers carry all of each 30 m span
# but half a bay at either end: 28.8 m + 27.0 m = 55.8 m, and
# 0.01 · 30 kg/m · 9.81 · 55.8 m = 164.22 N.
# - axial and moving_node: no node passes an idler; they deliver the law
#   to round-off (measured −8e-13 and −4e-8): held to 1e-4.
# - discrete (EI = 0): the belt turns by 0.225 rad over each return roll at
#   0.46 of its wave speed. Pressed on through the quadratic line round
#   each node, the nodes' passage pumped the spans (+34 %); on the quintic
#   running line it holds its law (measured +0.3 %): held to the 3 % of
#   that belt, with no warning (physics.md §5, §10).
# - discrete at a given 0.35 m element (the default is 0.0776 m here): 8.6
#   elements to a return bay, the quadratic line there, and the passage's
#   excess is back (measured +13.9 %).
#   The check must say so: not a pass, a warning that names the figures
#   and the remedies, a failed row in the checks table, a bad card in the
#   report.
# - a run that ends before its belt runs steadily is not judged: it says
#   why, and the checks table has no row for it.
# - design.secondary: individual (tests/data/static_individual.yaml, the
#   axial belt): the law takes the run's own loading, skirt, cleaner, wrap
#   and bearing resistances, 925 N of its 1166 N. Held to 1 %, and the law
#   to the static calculation's sum of the same resistances within 2 %
#   (wrap and bearings follow the run's tensions, not the static ones).
. "$(dirname "$0")/lib/setup.sh"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
sed 's/^simulation: .*/simulation: {duration: 20, tension_interval: 1}/' \
    "$DATA/idler_turn_loop.yaml" >"$tmp/loop.yaml"
# one line from summary.json: "ok ..." or "bad ..." for what is asked
verdict() {
    python3 - "$@" <<'PY' 2>&1
import json, sys
path, want = sys.argv[1], sys.argv[2]
s = json.load(open(path))
rf = s["running_force"]
rows = [c for c in s.get("checks", []) if c["check"].startswith("running force")]
warned = [w for w in s["warnings"] if w.startswith("running force:")]
law_hand = 0.01 * 30 * 9.81 * 55.8
if want == "exact":
    good = (rf["checked"] and rf["pass"] and abs(rf["error_rel"]) <= 1e-4
            and abs(rf["law_N"] - law_hand) <= 1e-6 * law_hand
            and rf["tolerance_rel"] == 0.01 and len(rows) == 1 and rows[0]["pass"]
            and not warned)
    print("ok" if good else "bad", rf, rows, warned)
elif want == "holds":
    good = (rf["checked"] and rf["pass"] and abs(rf["error_rel"]) <= 0.03
            and abs(rf["law_N"] - law_hand) <= 1e-6 * law_hand
            and rf["tolerance_rel"] == 0.03 and len(rows) == 1 and rows[0]["pass"]
            and not warned)
    print("ok" if good else "bad", "error %+.2f %%" % (100 * rf["error_rel"]), rf, rows, warned)
elif want == "excess":
    good = (rf["checked"] and not rf["pass"] and rf["error_rel"] > 0.03
            and abs(rf["law_N"] - law_hand) <= 1e-6 * law_hand
            and len(rows) == 1 and not rows[0]["pass"] and len(warned) == 1
            and "halve belt.element_length" in warned[0]
            and "bending stiffness" in warned[0] and "moving_node" in warned[0])
    print("ok" if good else "bad", "error %+.1f %%" % (100 * rf["error_rel"]), rf, rows,
          warned)
elif want == "unsteady":
    good = not rf["checked"] and "steady" in rf["why"] and not rows and not warned
    print("ok" if good else "bad", rf, rows)
elif want == "individual":
    st = json.load(open(sys.argv[3]))["resistances_N"]
    sec = sum(st[k] for k in ("loading_inertia", "loading_skirts", "skirts", "cleaners",
                              "wrap", "bearings"))
    good = (rf["checked"] and rf["pass"] and abs(rf["error_rel"]) <= 0.01
            and abs(rf["law_N"] - sec) <= 0.02 * sec and len(rows) == 1 and rows[0]["pass"])
    print("ok" if good else "bad", "law %.1f N, static's secondary %.1f N" % (rf["law_N"], sec),
          rf)
PY
}
sed "s/belt: {/belt: {element_length: 0.35, /" "$tmp/loop.yaml" >"$tmp/coarse.yaml"
for f in axial moving_node discrete coarse; do
    if [ "$f" != coarse ]; then
        sed "s/belt: {/belt: {formulation: $f, /" "$tmp/loop.yaml" >"$tmp/$f.yaml"
    fi
    "$BELTDYN" run "$tmp/$f.yaml" -o "$tmp/$f" --quiet >/dev/null 2>"$tmp/err" \
        || bad "run $f" "$(cat "$tmp/err")"
done
judge "axial: the law to round-off" "$(verdict "$tmp/axial/summary.json" exact)"
judge "moving_node: the law to round-off" "$(verdict "$tmp/moving_node/summary.json" exact)"
judge "discrete: the law within 3 %" "$(verdict "$tmp/discrete/summary.json" holds)"
judge "discrete, 0.3 m elements: the excess said" "$(verdict "$tmp/coarse/summary.json" excess)"
sed 's/duration: 20,/duration: 5,/' "$tmp/axial.yaml" >"$tmp/short.yaml"
"$BELTDYN" run "$tmp/short.yaml" -o "$tmp/short" --quiet >/dev/null 2>"$tmp/err" \
    || bad "run short" "$(cat "$tmp/err")"
judge "5 s run: not judged" "$(verdict "$tmp/short/summary.json" unsteady)"
# the report shows it
"$BELTDYN" report "$tmp/coarse" >/dev/null 2>"$tmp/err" || bad "report" "$(cat "$tmp/err")"
if grep -q 'card bad"><div class=k>running force</div><div class=v>+' "$tmp/coarse/report.html"; then
    ok "report: the running force card, marked bad"
else
    bad "report" "no bad running-force card in report.html"
fi
sed -e 's/  axial_stiffness: 1.0e7/  axial_stiffness: 1.0e7\n  formulation: axial/' \
    "$DATA/static_individual.yaml" >"$tmp/individual.yaml"
printf 'simulation: {duration: 30}\n' >>"$tmp/individual.yaml"
"$BELTDYN" static "$tmp/individual.yaml" --json >"$tmp/static.json" 2>"$tmp/err" \
    || bad "static" "$(cat "$tmp/err")"
"$BELTDYN" run "$tmp/individual.yaml" -o "$tmp/individual" --quiet >/dev/null 2>"$tmp/err" \
    || bad "run individual" "$(cat "$tmp/err")"
judge "design.secondary: individual" \
    "$(verdict "$tmp/individual/summary.json" individual "$tmp/static.json")"
tally
