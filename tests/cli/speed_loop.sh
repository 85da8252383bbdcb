#!/usr/bin/env bash
# The speed loop's `bandwidth` (docs/model-format.md `drive`, physics.md §6):
# 1. `check` on examples/head_drive.yaml prints the loop at its default
#    2 Hz, its K_p = 2ω_c·J against the belt's wave impedance at the drum
#    R²·2·√(EA·m′), and the bandwidth at which they would be equal.
# 2. The same model with that bandwidth: `check` says the loop's K_p is
#    1 x the impedance (printed to 3 digits): the key reaches the loop.
# 3. `bandwidth: 0` is refused at its line with exit 2, and `run` writes
#    nothing.
. "$(dirname "$0")/lib/setup.sh"
ex="$EXAMPLES/head_drive.yaml"

"$BELTDYN" check "$ex" >"$tmp/out" 2>"$tmp/err"
line=$(grep "^speed loop head: " "$tmp/out")
if echo "$line" | grep -qE "^speed loop head: 2 Hz on [0-9.e+]+ kg m2, K_p [0-9.e+]+ N m s, [0-9.]+ x the belt's wave impedance at the drum \([0-9.e+]+ N m s; at drive.bandwidth: [0-9.e+-]+ Hz"; then
    ok "check prints: $line"
else
    bad "speed loop line" "$line $(cat "$tmp/err")"
fi
matched=$(echo "$line" | sed -E 's/.*at drive.bandwidth: ([0-9.e+-]+) Hz.*/\1/')

sed "s/      inertia: 20$/      inertia: 20\n      bandwidth: $matched/" "$ex" >"$tmp/matched.yaml"
"$BELTDYN" check "$tmp/matched.yaml" >"$tmp/out2" 2>"$tmp/err2"
line2=$(grep "^speed loop head: " "$tmp/out2")
if grep -q "bandwidth: $matched" "$tmp/matched.yaml" && echo "$line2" | grep -q " 1 x the belt's wave impedance"; then
    ok "bandwidth $matched Hz: $line2"
else
    bad "matched bandwidth" "$line2 $(cat "$tmp/err2")"
fi

sed "s/      inertia: 20$/      inertia: 20\n      bandwidth: 0/" "$ex" >"$tmp/zero.yaml"
want=$(grep -n "bandwidth: 0" "$tmp/zero.yaml" | cut -d: -f1)
"$BELTDYN" run "$tmp/zero.yaml" -o "$tmp/zero_out" >"$tmp/out3" 2>"$tmp/err3"; rc=$?
if [ $rc -eq 2 ] && grep -qE "^$tmp/zero.yaml:$want:[0-9]+: error: .*bandwidth" "$tmp/err3" && [ ! -e "$tmp/zero_out" ]; then
    ok "bandwidth: 0 refused: $(head -1 "$tmp/err3")"
else
    bad "bandwidth: 0" "exit $rc: $(cat "$tmp/err3")"
fi
tally
