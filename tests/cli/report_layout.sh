#!/usr/bin/env bash
# What a run writes beside the contract for its report, and the report's
# use of it, on 1 s of examples/head_drive.yaml (stabilized, a gravity
# takeup of 2500 kg under a 200 kg pulley, a 6000 N·m max_torque drive):
# - summary.json "layout": pulley centres as in the file, wraps, the takeup
#   axis, the drive's rating, a closed belt path whose polygon is as long as
#   the belt, the loaded region from the feed to the discharge;
# - parts.csv: at history's times, the drive's tight and slack sides and the
#   takeup's pull, which at rest is the hanging weight (2700 kg · g);
# - the report draws the layout, marks the pulleys on its s axes, plots
#   torque against the rating, the friction used, and the takeup's pull.
. "$(dirname "$0")/lib/setup.sh"

sed -e 's/^  duration: 12$/  duration: 1/' "$EXAMPLES/head_drive.yaml" >"$tmp/m.yaml"
"$BELTDYN" run "$tmp/m.yaml" -o "$tmp/run" --quiet >/dev/null 2>&1 || bad "run" "failed"
"$BELTDYN" report "$tmp/run" >/dev/null 2>&1 || bad "report" "failed"

python3 - "$tmp/run" "$tmp/m.yaml" >"$tmp/verdicts" 2>&1 <<'PY' || bad "checker" "crashed: $(cat "$tmp/verdicts")"
import csv, json, math, sys
run, model = sys.argv[1], sys.argv[2]
s = json.load(open(run + "/summary.json"))
lay = s["layout"]
def say(cond, what, detail=""):
    print(("ok " if cond else "bad ") + what + ("" if cond else " | " + detail))

# pulleys as in the file (x, y, radius from examples/head_drive.yaml)
want = {"head": (50, 1, 0.4), "bend1": (46, 0.2, 0.4), "takeup": (45.2, -4, 0.4),
        "bend2": (44.4, 0.2, 0.4), "tail": (0, 1, 0.4)}
got = {p["name"]: p for p in lay["pulleys"]}
say(sorted(got) == sorted(want), "layout lists every pulley", str(sorted(got)))
# the takeup stands where the belt was laid round it: moved along its axis
# (0, -1) by takeup_shift_m, a few mm for the lumped belt's polygon
shift = got["takeup"]["takeup_shift_m"]
say(0 <= abs(shift) < 0.01, "takeup laid within 1 cm of the file's centre", "%g m" % shift)
want["takeup"] = (45.2, -4 - shift, 0.4)
worst = max(abs(got[n]["x_m"] - w[0]) + abs(got[n]["y_m"] - w[1]) + abs(got[n]["radius_m"] - w[2])
            for n, w in want.items() if n in got)
say(worst < 1e-9, "pulley centres and radii as in the file (the takeup shifted)", "off by %g" % worst)
# hand geometry of the wraps: head and tail turn the belt 180°, the bends 90°
# (horizontal strands, vertical takeup loop), the takeup 180°
wraps = {"head": 180, "tail": 180, "bend1": 90, "bend2": 90, "takeup": 180}
werr = max(abs(got[n]["wrap_deg"] - w) for n, w in wraps.items())
say(werr < 1e-9, "wrap angles 180/90/180/90/180°", "off by %g°" % werr)
say(got["takeup"]["takeup"] and got["takeup"]["takeup_axis"] == [0, -1], "takeup axis (0, -1)",
    str(got["takeup"].get("takeup_axis")))
say(got["head"]["drive"] and got["head"].get("max_torque_Nm") == 6000, "drive rating 6000 N·m",
    str(got["head"]))
# the wraps' order on s follows travel: s = 0 leaves the head
order = sorted(want, key=lambda n: got[n]["s_start_m"])
say(order == ["bend1", "takeup", "bend2", "tail", "head"], "wraps in travel order on s", str(order))
# the path: closed, and its polygon as long as the belt (2° arcs: the chord
# error θ²/24 on 1.9 m of arc is 1e-4 m)
p = lay["path"]
pts = list(zip(p["x_m"], p["y_m"]))
gap = math.dist(pts[0], pts[-1])
say(gap < 1e-9, "path closes", "gap %g m" % gap)
L = sum(math.dist(a, b) for a, b in zip(pts, pts[1:]))
say(abs(L - s["belt_length_m"]) < 1e-3, "path length = belt length within 1 mm",
    "%.6f vs %.6f" % (L, s["belt_length_m"]))
say(abs(lay["belt_length_m"] - s["belt_length_m"]) < 1e-12, "layout's belt length", "")
# hand geometry of the belt loop: the wraps' arcs R·φ, and the straights:
# carry 50 m (tail to head); return head → bend1 50 − 46 = 4 m; bend1 →
# takeup and takeup → bend2 0.2 − y_takeup each; bend2 → tail 44.4 m
arc = sum(math.radians(wraps[n]) * want[n][2] for n in want)
straight = 50 + 4 + 2 * (0.2 - want["takeup"][1]) + 44.4
say(abs(s["belt_length_m"] - (arc + straight)) < 1e-9, "belt length = hand geometry",
    "%.9f vs %.9f" % (s["belt_length_m"], arc + straight))
# loaded region: feed to the discharge pulley's wrap (the head)
ld = lay["loaded"]
end = (ld["feed_s_m"] + ld["length_m"]) % s["belt_length_m"]
say(abs(end - got["head"]["s_start_m"]) < 1e-9, "loaded region ends where the belt reaches the head",
    "%g vs %g" % (end, got["head"]["s_start_m"]))

# parts.csv
rows = list(csv.reader(open(run + "/parts.csv")))
say(rows[0] == ["t_s", "head.tight_N", "head.slack_N", "takeup.pull_N"], "parts.csv header",
    str(rows[0]))
hist = [r[0] for r in csv.reader(open(run + "/history.csv"))][1:]
say([r[0] for r in rows[1:]] == hist, "parts.csv at history's times", "")
pull0 = float(rows[1][3])
weight = 2700 * 9.81
say(abs(pull0 - weight) <= 1e-3 * weight, "takeup pull at rest = hanging weight within 0.1 %",
    "%g vs %g N" % (pull0, weight))
html = open(run + "/report.html").read()
for what in ["plots/layout.svg", "friction they use", "pull on the carriage", "share of its rating"]:
    say(what in html, "report.html: " + what, "")
PY
while read -r verdict rest; do
    case "$verdict" in
        ok) ok "$rest" ;;
        *) bad "${rest%% | *}" "${rest#* | }" ;;
    esac
done <"$tmp/verdicts"
# a takeup held at the end of its travel fails its check, with a warning
sed -e 's/^      mass: 2500$/      mass: 2500\n      travel: [-0.001, 0.001]/' "$tmp/m.yaml" >"$tmp/limit.yaml"
grep -q "travel: \[-0.001" "$tmp/limit.yaml" || bad "limit model" "sed found no takeup mass"
"$BELTDYN" run "$tmp/limit.yaml" -o "$tmp/limit" --quiet >/dev/null 2>&1
python3 - "$tmp/limit/summary.json" <<'PY' >"$tmp/limit.txt" 2>&1 && ok "takeup at its travel limit fails 'takeup travel out' and warns" || bad "takeup at its limit" "$(cat "$tmp/limit.txt")"
import json, sys
s = json.load(open(sys.argv[1]))
c = [c for c in s["checks"] if c["check"] == "takeup travel out, takeup"]
assert len(c) == 1 and c[0]["value"] == c[0]["limit"] == 0.001 and not c[0]["pass"], s["checks"]
assert c[0]["limit_is"] == "below", c
assert any("reached the end of its travel" in w for w in s["warnings"]), s["warnings"]
PY
for p in layout drives takeups envelope; do
    [ -s "$tmp/run/plots/$p.png" ] && ok "plots/$p.png" || bad "plots/$p.png" "missing"
done
tally
