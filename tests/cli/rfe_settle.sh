#!/usr/bin/env bash
# The rfe belt starts static in its own equilibrium, and its energy account
# holds from the first step.
#
# A chain of rigid elements cannot lie with every centre on the string's
# path where the path's curvature jumps (docs/physics.md §15, *Settled where
# it is laid*): on examples/flat_belt_drive.yaml at the rfe belt's default
# element the static layout held 0.56 J of shear and alignment in 2.4 J,
# which the centres' zigzag (the mode at the step's limit) let go in two
# steps; the energy account, which books that mode's energy at some times
# what the scheme keeps of it, missed 0.12 J, and the run's balance read
# 4.5 % (its summary's energy check failed). The build now lets the chain
# settle where it is laid: 1.7e-4 (a full stabilization 1.5e-4).
#
# Here: its first 0.3 s on the rfe belt. The balance within 1e-3 (the
# settled run's is 1.7e-4, its worst at 0.04 s; unsettled it is 4.5e-2),
# no failed check, and the summary says the belt settled. Laid at rest
# (`initial_state: rest`, unstretched; it snaps to tension as it starts)
# the chain holds the same misfit: its 1.5 s run within 5e-3 (settled
# 1.0e-3; unsettled 0.114 over 2 s, the discrete belt 3.4e-6), its
# checks those of the discrete belt laid at rest.
set -u
. "$(dirname "$0")/lib/setup.sh"

sed -e 's/^belt:/belt:\n  formulation: rfe/' -e 's/^  duration: .*/  duration: 0.3/' \
    "$EXAMPLES/flat_belt_drive.yaml" >"$tmp/rfe.yaml"
grep -q '^  duration: 0.3$' "$tmp/rfe.yaml" || bad "model" "the example has no duration to shorten"

if ! "$BELTDYN" run "$tmp/rfe.yaml" -o "$tmp/out" --quiet >/dev/null 2>"$tmp/err"; then
    bad "rfe run" "$(tail -3 "$tmp/err")"
else
    judge "rfe flat belt drive: settled, balance within 1e-3" "$(python3 - "$tmp/out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
bal = s["energy"]["balance_error_rel"]
failed = [c["check"] for c in s["checks"] if not c["pass"]]
st = s.get("settle")
if st is None or st["steps"] <= 0:
    print("no settle in the summary: %s" % st)
elif not bal <= 1e-3 or failed:
    print("balance %.3g (limit 1e-3), failed checks %s" % (bal, failed))
else:
    print("ok: balance %.3g, settled in %d steps letting %.3g J go" %
          (bal, st["steps"], st["released_J"]))
PY
)"
fi

# laid at rest, the example's 1.5 s (the snap and the start), against the
# discrete belt's checks
sed -e 's/^simulation:/simulation:\n  initial_state: rest/' "$EXAMPLES/flat_belt_drive.yaml" \
    >"$tmp/disc_rest.yaml"
sed -e 's/^belt:/belt:\n  formulation: rfe/' "$tmp/disc_rest.yaml" >"$tmp/rfe_rest.yaml"
for belt in disc_rest rfe_rest; do
    "$BELTDYN" run "$tmp/$belt.yaml" -o "$tmp/$belt" --quiet >/dev/null 2>"$tmp/$belt.err" ||
        bad "$belt run" "$(tail -3 "$tmp/$belt.err")"
done
if [ -f "$tmp/rfe_rest/summary.json" ] && [ -f "$tmp/disc_rest/summary.json" ]; then
    judge "rfe flat belt drive laid at rest: settled, balance within 5e-3" "$(python3 - "$tmp" <<'PY'
import json, sys
r = json.load(open(sys.argv[1] + "/rfe_rest/summary.json"))
d = json.load(open(sys.argv[1] + "/disc_rest/summary.json"))
bal = r["energy"]["balance_error_rel"]
fr = sorted(c["check"] for c in r["checks"] if not c["pass"])
fd = sorted(c["check"] for c in d["checks"] if not c["pass"])
if r.get("settle") is None or not bal <= 5e-3 or fr != fd:
    print("settle %s, balance %.3g (limit 5e-3), failed checks %s (discrete %s)" %
          (r.get("settle"), bal, fr, fd))
else:
    print("ok: balance %.3g (discrete %.3g), failed checks as the discrete belt's %s" %
          (bal, d["energy"]["balance_error_rel"], fr))
PY
)"
fi
tally
