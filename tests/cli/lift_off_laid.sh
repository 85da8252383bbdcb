#!/usr/bin/env bash
# A belt laid on its idlers does not lift off them as the run starts.
#
# The belt is laid straight on the roll tops (model-format.md
# `initial_state: static`); where it turns over an idler (its sag, a curve)
# the contact stands the corner the belt's line cuts over it below the roll
# top (belt/lumped/idler_contact.c). On the cement plant's carry at its
# 0.2 m elements that corner is 1.04 mm, just above the 1 mm that counts as
# lifted: until 2026-12-02 the first step reported all 809 carry stations
# lifted for 15 ms, while the belt only fell 1 mm onto them, and the
# example's checks failed "lift-off from the idlers". A station counts
# once the belt has stood within half the clearance of it; a belt that
# leaves an idler it stood on is still reported (the concave curves of
# test_profile and cli_profile_600m).
#
# Here: the example's first 0.1 s (the drive creeping, no lift possible on
# a level conveyor) on the discrete belt and on the rfe belt at its own
# element: no lift-off, no failed check.
set -u
. "$(dirname "$0")/lib/setup.sh"

sed -e 's/^  duration: .*/  duration: 0.1/' "$EXAMPLES/cement_plant.yaml" >"$tmp/discrete.yaml"
sed -e 's/^belt:/belt:\n  formulation: rfe/' -e '/^  element_length:/d' "$tmp/discrete.yaml" \
    >"$tmp/rfe.yaml"
grep -q '^  duration: 0.1$' "$tmp/discrete.yaml" || bad "model" "the example has no duration to shorten"

for belt in discrete rfe; do
    if ! "$BELTDYN" run "$tmp/$belt.yaml" -o "$tmp/$belt" --quiet >/dev/null 2>"$tmp/$belt.err"; then
        bad "$belt run" "$(tail -3 "$tmp/$belt.err")"
        continue
    fi
    judge "$belt: laid on its idlers, no lift-off" "$(python3 - "$tmp/$belt/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
lo = s["lift_off"]
failed = [c["check"] for c in s["checks"] if not c["pass"]]
if lo.get("occurred") or failed:
    print("lift_off %s, failed checks %s" % (lo, failed))
else:
    print("ok: %d steps, checked %s, no failed check" % (s["steps"], lo["checked"]))
PY
)"
done
tally
