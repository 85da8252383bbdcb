#!/usr/bin/env bash
# issue 13: the flexible boom at rest obeys virtual work: the telescopic
# cylinder's force equals the derivative of the boom's potential energy
# (gravity + sections + pads + ropes + the cylinder's oil column,
# history.csv potential_J) with the stroke, F = dΠ/ds, by central
# differences over 7.95 -> 8.05 m. examples/telescopic_boom.yaml without
# friction (friction locks in whatever state settling leaves), 4 elements
# per segment, settled at each stroke. Within 1 %: what settling to 1e-5
# m/s leaves (measured 0.3 %). A pad law not derived from an energy fails
# this: measuring the outer contact in the pads' own frame instead of the
# surface's gave 482.2 kN against dΠ/ds = 468.6 kN (2.9 %). Also the force
# is below rope statics, g sin θ (m2 + 2 (m3 + m_tip)) = 499.8 kN, by the
# sag the extension releases (-1 % to -10 % allowed; measured -6 %).
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for s in 7.95 8.05; do
    sed -e 's/elements_per_segment: 8/elements_per_segment: 4/' \
        -e 's/friction: {static: 0.15, dynamic: 0.10}/friction: {static: 0, dynamic: 0}/' \
        -e "s/initial: 2.0/initial: $s/" -e "s/profile: {kind: cubic.*}/profile: [[0, $s], [1, $s]]/" \
        -e 's/duration: 18/duration: 0.01/' "$EXAMPLES/telescopic_boom.yaml" > "$work/$s.yaml"
    grep -q 'static: 0, dynamic: 0' "$work/$s.yaml"
    "$BELTDYN" run "$work/$s.yaml" -o "$work/$s" -q
    grep -q '"warnings":	\[\]' "$work/$s/summary.json" || { cat "$work/$s/summary.json"; exit 1; }
done
python3 - "$work" <<'PY'
import csv, math, sys
w = sys.argv[1]
a = next(csv.DictReader(open(w + '/7.95/history.csv')))
b = next(csv.DictReader(open(w + '/8.05/history.csv')))
dpi = (float(b['potential_J']) - float(a['potential_J'])) / 0.1
F = 0.5 * (float(a['telescopic_cylinder_N']) + float(b['telescopic_cylinder_N']))
statics = 9.81 * math.sin(math.radians(60)) * (304.07 * 10 + 2 * (289.27 * 10 + 25000))
dev, sag = F / dpi - 1, F / statics - 1
print("boom at rest at 8 m: cylinder %.0f N, dPi/ds %.0f N (%+.2f %%); %+.1f %% of rope statics"
      % (F, dpi, 100 * dev, 100 * sag))
sys.exit(0 if abs(dev) <= 0.01 and -0.10 <= sag <= -0.01 else 1)
PY
