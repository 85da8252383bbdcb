#!/usr/bin/env bash
# The axial examples end to end (issue 5): `check`, `run` and `report` on
# examples/overland_axial.yaml (shortened to 3 s) and
# examples/vbelt_dol_axial.yaml (its 6 s start). The V-belt drive must slip
# during its direct-on-line start and the conveyor reach its speed; both
# runs keep their energy balance (cli.md) within 1% and warn of nothing.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
EXAMPLES="${EXAMPLES:-$(cd "$(dirname "$0")/../../examples" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sed -e 's/^\(  duration:\).*/\1 3/' "$EXAMPLES/overland_axial.yaml" >"$tmp/overland.yaml"
grep -q '^  duration: 3$' "$tmp/overland.yaml" || { echo "FAIL could not shorten the model"; exit 1; }
cp "$EXAMPLES/vbelt_dol_axial.yaml" "$tmp/vbelt.yaml"

for m in overland vbelt; do
    if ! "$BELTDYN" check "$tmp/$m.yaml" >"$tmp/$m.check" 2>&1; then
        echo "FAIL beltdyn check $m"; cat "$tmp/$m.check"; exit 1
    fi
    grep -q '^formulation: axial' "$tmp/$m.check" || { echo "FAIL check $m does not say axial"; exit 1; }
    if ! "$BELTDYN" run "$tmp/$m.yaml" -o "$tmp/$m" --quiet >/dev/null 2>"$tmp/$m.err"; then
        echo "FAIL beltdyn run $m"; cat "$tmp/$m.err"; exit 1
    fi
    if ! "$BELTDYN" report "$tmp/$m" >/dev/null 2>"$tmp/$m.err"; then
        echo "FAIL beltdyn report $m"; cat "$tmp/$m.err"; exit 1
    fi
    [ -s "$tmp/$m/report.html" ] || { echo "FAIL no report.html for $m"; exit 1; }
    echo "ok   $m: check, run, report"
done

python3 - "$tmp/overland/summary.json" "$tmp/vbelt/summary.json" <<'PY'
import json, sys
ov, vb = (json.load(open(p)) for p in sys.argv[1:3])
fails = []
def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        fails.append(what)
for name, s in (("overland", ov), ("vbelt", vb)):
    check(s["status"] == "completed", name + " completed")
    check(s["energy"]["balance_error_rel"] < 0.01, "%s energy balance within 1 percent (%.2g)" % (name, s["energy"]["balance_error_rel"]))
    # vbelt's short fabric belt sags 70-76 % of its axial compliance into its
    # idler bays, none of which the axial belt holds: warned, and true (its
    # start peaks 25 % higher on the discrete belt, docs/physics.md section
    # 14); any other warning fails
    other = [w for w in s["warnings"] if "sag between its idlers" not in w]
    sag = len(s["warnings"]) - len(other)
    check(other == [] and sag == (2 if name == "vbelt" else 0),
          "%s has no warnings but %d on its sag (%s)" % (name, sag, other))
head = vb["pulleys"]["head"]
check(head.get("transmission_slip_max_mps", 0) > 0.5, "the V belt slips during the DOL start (%.2f m/s)" % head.get("transmission_slip_max_mps", 0))
check(head["omega_final_rad_s"] * 0.25 > 3.0, "the conveyor reaches its speed (%.2f m/s)" % (head["omega_final_rad_s"] * 0.25))
check(ov["pulleys"]["takeup"]["travel_max_m"] > 0.0, "the overland takeup moves")
sys.exit(1 if fails else 0)
PY
