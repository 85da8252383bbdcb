#!/usr/bin/env bash
# Determinism (issue 2): the same model run twice gives bit-identical
# outputs: history.csv, tension.csv and envelope.csv byte for byte, and
# summary.json identical except its wall_time_s line.
set -u
. "$(dirname "$0")/lib/setup.sh"

model="$EXAMPLES/flat_belt_drive.yaml"
for k in 1 2; do
    "$BELTDYN" run "$model" -o "$tmp/run$k" >"$tmp/run$k.out" 2>"$tmp/run$k.err"
    rc=$?
    if [ $rc -eq 0 ]; then ok "run $k exits 0"
    else bad "run $k" "exit $rc: $(cat "$tmp/run$k.err")"; fi
done

for f in history.csv tension.csv envelope.csv; do
    if [ ! -s "$tmp/run1/$f" ] || [ ! -s "$tmp/run2/$f" ]; then
        bad "$f" "missing or empty"
    elif cmp -s "$tmp/run1/$f" "$tmp/run2/$f"; then
        ok "$f byte-identical ($(wc -l <"$tmp/run1/$f") lines)"
    else
        bad "$f" "differs: $(cmp "$tmp/run1/$f" "$tmp/run2/$f" 2>&1 | head -1)"
    fi
done

s1="$tmp/run1/summary.json" s2="$tmp/run2/summary.json"
# the wall_time_s value, whatever the layout of the file
wall_re='"wall_time_s":[[:space:]]*[-0-9.eE+]+'
if [ ! -s "$s1" ] || [ ! -s "$s2" ]; then
    bad "summary.json" "missing or empty"
elif ! grep -qE "$wall_re" "$s1" || ! grep -qE "$wall_re" "$s2"; then
    bad "summary.json" "no numeric wall_time_s"
elif diff <(sed -E "s/$wall_re/\"wall_time_s\": X/" "$s1") \
          <(sed -E "s/$wall_re/\"wall_time_s\": X/" "$s2") >"$tmp/summary.diff"; then
    ok "summary.json identical except wall_time_s"
else
    bad "summary.json" "differs beyond wall_time_s: $(head -5 "$tmp/summary.diff")"
fi

tally
