#!/usr/bin/env bash
# `beltdyn run` on a model with a `design` section adds the design-standard
# calculation to summary.json: an object "static" (as `static --json`) and
# the top-level "T_min_sag_N". examples/head_drive.yaml, shortened to 0.2 s
# without stabilization.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
EXAMPLES="${EXAMPLES:-$(cd "$(dirname "$0")/../../examples" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

sed -e 's/^\(  duration:\).*/\1 0.2/' -e 's/^\(  stabilize:\).*/\1 false/' \
    "$EXAMPLES/head_drive.yaml" >"$tmp/head_drive.yaml"
grep -q '^  duration: 0.2$' "$tmp/head_drive.yaml" || { echo "FAIL could not shorten the model"; exit 1; }
grep -q '^  stabilize: false$' "$tmp/head_drive.yaml" || { echo "FAIL could not turn off stabilize"; exit 1; }

if ! "$BELTDYN" run "$tmp/head_drive.yaml" -o "$tmp/out" --quiet >"$tmp/stdout" 2>"$tmp/stderr"; then
    echo "FAIL beltdyn run exited nonzero"; cat "$tmp/stderr"; exit 1
fi
python3 - "$tmp/out/summary.json" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
fails = []
def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        fails.append(what)
def num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
st = s.get("static")
check(isinstance(st, dict), 'summary has a "static" object')
st = st if isinstance(st, dict) else {}
check(num(st.get("T1_N")) and st["T1_N"] > 0, 'static.T1_N is a positive number')
check(num(st.get("T_min_sag_N")) and st["T_min_sag_N"] > 0, 'static.T_min_sag_N is a positive number')
check(num(s.get("T_min_sag_N")), 'top-level T_min_sag_N is a number')
check(s.get("T_min_sag_N") == st.get("T_min_sag_N"), 'top-level T_min_sag_N equals static.T_min_sag_N')
check(st.get("standard") == "din22101", 'static.standard is the model\'s (din22101)')
check(isinstance(s.get("warnings"), list), 'warnings is a list')
sys.exit(1 if fails else 0)
PY
