#!/usr/bin/env bash
# issue 13: the luffing cylinder's force at rest at the start (2 m) and the
# end (8 m) of the seed's stroke, examples/telescopic_boom.yaml's geometry
# (the seed's pivot 956 mm behind and 556 mm above section 1's bottom end,
# pivot_offset) on 4 elements per segment, held at each stroke:
# - the end/start ratio against the seed's (Figs. 18 and 27: 236.49/139.86
#   = 1.691 for 1 t, 1260.66/698.89 = 1.804 for 25 t) within 5 %, the
#   issue's bound (measured 0.3 %, 0.2 %);
# - the start force against rigid statics of that geometry (what `check`
#   prints) within 3 %: the flexible boom's sag moves the load outward
#   (measured +0.3 % for 1 t, +2.1 % for 25 t);
# - without the rod, the pivot moment against rigid statics likewise.
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() {   # name mass stroke [norod]
    sed -e 's/elements_per_segment: 8/elements_per_segment: 4/' -e "s/mass: 25000/mass: $2/" \
        -e "s/initial: 2.0/initial: $3/" -e "s/profile: {kind: cubic.*}/profile: [[0, $3], [1, $3]]/" \
        -e 's/duration: 18/duration: 0.01/' "$EXAMPLES/telescopic_boom.yaml" > "$work/$1.yaml"
    if [ "${4:-}" = norod ]; then sed -i '/luffing_cylinder:/d' "$work/$1.yaml"; fi
    grep -q "profile: \[\[0, $3\]" "$work/$1.yaml"
    "$BELTDYN" check "$work/$1.yaml" > "$work/$1.check"
    "$BELTDYN" run "$work/$1.yaml" -o "$work/$1" -q
    grep -q '"status":	"completed"' "$work/$1/summary.json" || { cat "$work/$1/summary.json"; exit 1; }
    grep -q '"warnings":	\[\]' "$work/$1/summary.json" || { cat "$work/$1/summary.json"; exit 1; }
}
run a1 1000 2.0; run b1 1000 8.0; run a25 25000 2.0; run b25 25000 8.0; run m1 1000 2.0 norod
python3 - "$work" <<'PY'
import csv, re, sys
w = sys.argv[1]
def first(name):
    return float(next(csv.DictReader(open('%s/%s/history.csv' % (w, name))))['luffing_N'])
def statics(name):
    m = re.search(r'by rigid statics: (\S+) ', open('%s/%s.check' % (w, name)).read())
    return float(m.group(1))
ok = True
for m, seed in ((1, 236.49 / 139.86), (25, 1260.66 / 698.89)):
    a, b = first('a%d' % m), first('b%d' % m)
    dev = b / a / seed - 1
    sdev = a / statics('a%d' % m) - 1
    print("%2d t: luffing cylinder %.0f N at 2 m, %.0f N at 8 m: ratio %.4f, the seed's %.4f "
          "(%+.2f %%); at 2 m %+.2f %% of rigid statics" % (m, a, b, b / a, seed, 100 * dev, 100 * sdev))
    ok = ok and abs(dev) <= 0.05 and 0.0 <= sdev <= 0.03
mm = first('m1') / statics('m1') - 1
print(" 1 t without the rod: pivot moment %.0f N·m, %+.2f %% of rigid statics" % (first('m1'), 100 * mm))
ok = ok and 0.0 <= mm <= 0.03
sys.exit(0 if ok else 1)
PY
