#!/usr/bin/env bash
# `check` says, for the discrete (and rfe) belt without bending stiffness, by how
# much each idler set turns the belt at rest, φ = m'g·a·cos δ/(T − m'v²),
# and how fast the belt runs against its wave speed √(T/m'), and warns
# where φ ≥ 0.10 rad at v ≥ 0.2·c and the idlers press on the quadratic
# running line: on such spans that belt has drawn running force above its
# resistance law (docs/physics.md §10), on the discrete belt's quintic line
# it does not (§5). A level, empty loop at 6 m/s and 5000 N: the 3 m
# return bays turn it by 30·9.81·3/(5000 − 30·36) = 0.225 rad at
# 6/√(5000/30) = 0.46 of its wave speed, the 1.2 m carry bays by
# 0.090 rad. At the discrete belt's default element (0.0776 m, halved)
# both sets press on the quintic line: not warned. At a given 0.35 m
# element the return's 8.6 elements to a bay put it on the quadratic line:
# warned, the carry (0.090 rad) not. The
# count takes the installed 5000 N; at rest the spans hang at somewhat
# different tensions (the sag stretches the belt, the pulleys' friction
# holds the difference: the carry's angle reads 4 % under the count), so
# each angle is held to 5 % of it. With bending stiffness, or on the
# moving-node belt, nothing is said; the rfe belt is counted as the
# discrete one (its default element is 0.0776 m whatever its idlers, and a
# given one spanning more than 19.5° of a pulley is warned of: 0.15 m,
# 28.6° of these). `run` puts the same warning into summary.json (and so
# into the report) for the return span alone.
. "$(dirname "$0")/lib/setup.sh"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
cp "$DATA/idler_turn_loop.yaml" "$tmp/loop.yaml"
"$BELTDYN" check "$tmp/loop.yaml" >"$tmp/out" 2>"$tmp/err" || bad "check" "$(cat "$tmp/err")"
ret=$(grep "^  span head" "$tmp/out" | sed -n 's/.*turns \([0-9.]*\) rad.*/\1/p')
if [ -n "$ret" ] && awk -v p="$ret" 'BEGIN { exit !(p > 0.225 * 0.95 && p < 0.225 * 1.05) }'; then
    ok "return bays: $ret rad (hand count 0.225)"
else
    bad "return bays' turn" "got '$ret' in: $(grep '^  span head' "$tmp/out")"
fi
car=$(grep "^  span tail" "$tmp/out" | sed -n 's/.*turns \([0-9.]*\) rad.*/\1/p')
if [ -n "$car" ] && awk -v p="$car" 'BEGIN { exit !(p > 0.090 * 0.95 && p < 0.090 * 1.05) }'; then
    ok "carry bays: $car rad (hand count 0.090)"
else
    bad "carry bays' turn" "got '$car' in: $(grep '^  span tail' "$tmp/out")"
fi
if ! grep -q "^warning: the idlers of span" "$tmp/out" \
    && grep -q "^  span head .*running line quintic" "$tmp/out" \
    && grep -q "^  span tail .*running line quintic" "$tmp/out"; then
    ok "default element: both sets on the quintic line, not warned"
else
    bad "default element" "$(grep '^warning\|running line' "$tmp/out")"
fi
sed 's/belt: {/belt: {element_length: 0.35, /' "$tmp/loop.yaml" >"$tmp/coarse.yaml"
"$BELTDYN" check "$tmp/coarse.yaml" >"$tmp/out" 2>"$tmp/err" || bad "check" "$(cat "$tmp/err")"
if grep -q "^warning: the idlers of span 'head'.*quintic running line" "$tmp/out" \
    && ! grep -q "^warning: the idlers of span 'tail'" "$tmp/out" \
    && grep -q "^  span head .*running line quadratic" "$tmp/out"; then
    ok "0.35 m elements: warned for the return span only"
else
    bad "warnings" "$(grep '^warning\|running line' "$tmp/out")"
fi
"$BELTDYN" run "$tmp/coarse.yaml" -o "$tmp/run" >/dev/null 2>"$tmp/err" \
    || bad "run" "$(cat "$tmp/err")"
if grep -q "the idlers of span 'head' turn the belt" "$tmp/run/summary.json" \
    && ! grep -q "the idlers of span 'tail'" "$tmp/run/summary.json"; then
    ok "run: summary.json warns for the return span only"
else
    bad "run's warnings" "$(grep -A3 '"warnings"' "$tmp/run/summary.json")"
fi
# the rfe belt's element centres meet the idlers as the discrete belt's
# nodes do (docs/physics.md §15): the same angles and running lines; its
# default element is 15° of the 0.3 m pulleys, 0.0776 m (model-format.md),
# shortened for its polygon on the pulleys (belt/lumped/polygon.c): at
# 6 m/s on 30 kg/m, 0.65·m′v²·2·(0.0776/0.3)³ = 24.3 N against the idlers'
# 0.01·g·30 kg/m·60 m = 176.6 N, 13.8 %, so by the most it is shortened,
# half, to 0.0388 m and 13.8/8 = 1.7 %. Both sets press on the quintic
# line there: not warned. A given 0.15 m
# element (28.6° of a pulley) is warned of, as the chain on a sprocket its
# rigid elements then make (belt/rfe/build.c)
sed 's/belt: {/belt: {formulation: rfe, /' "$tmp/loop.yaml" >"$tmp/rfe.yaml"
"$BELTDYN" check "$tmp/rfe.yaml" >"$tmp/out_rfe" 2>"$tmp/err" || bad "check rfe" "$(cat "$tmp/err")"
rret=$(grep "^  span head" "$tmp/out_rfe" | sed -n 's/.*turns \([0-9.]*\) rad.*/\1/p')
if [ -n "$rret" ] && [ "$rret" = "$ret" ] \
    && [ "$(grep -c '^  span .*running line quintic$' "$tmp/out_rfe")" = 2 ] \
    && ! grep -q "^warning: the idlers of span\|^warning: a belt element spans" "$tmp/out_rfe" \
    && grep -q "^belt elements: .*(unstretched length 0.0388 m; the rfe belt's default, 15°.*shortened" \
        "$tmp/out_rfe" \
    && grep -q "^rfe polygon on the pulleys: about 1.7 % of the running resistance" "$tmp/out_rfe"; then
    ok "rfe: return bays $rret rad, 15° default element shortened to half for its polygon (1.7 %), both sets quintic, not warned"
else
    bad "rfe" "$(grep 'elements:\|turns\|^warning' "$tmp/out_rfe")"
fi
sed 's/belt: {/belt: {formulation: rfe, element_length: 0.15, /' "$tmp/loop.yaml" >"$tmp/rfe_coarse.yaml"
"$BELTDYN" check "$tmp/rfe_coarse.yaml" >"$tmp/out_rfe_coarse" 2>"$tmp/err" \
    || bad "check rfe 0.15 m" "$(cat "$tmp/err")"
if grep -q "^warning: a belt element spans 29° of pulley .*ride a pulley as a chain rides a sprocket" \
    "$tmp/out_rfe_coarse"; then
    ok "rfe, 0.15 m elements: warned of the chain on a sprocket"
else
    bad "rfe 0.15 m" "$(grep '^warning' "$tmp/out_rfe_coarse")"
fi
# and of its polygon's running force: 0.65·30·6²·2·(0.15/0.3)³ = 175.5 N
# against 176.6 N, 99.4 % (the cube from the default's 13.8 %, above)
if grep -q "^warning: the rfe belt's elements (0.15 m) ride its pulleys as a polygon that costs about 99.[0-9] %" \
    "$tmp/out_rfe_coarse"; then
    ok "rfe, 0.15 m elements: warned of the polygon's running force, 99 %"
else
    bad "rfe 0.15 m polygon" "$(grep '^warning' "$tmp/out_rfe_coarse")"
fi
sed 's/initial_tension: 5000}/initial_tension: 5000, bending_stiffness: 20}/' \
    "$tmp/loop.yaml" >"$tmp/ei.yaml"
sed 's/belt: {/belt: {formulation: moving_node, /' "$tmp/loop.yaml" >"$tmp/mn.yaml"
for m in ei mn; do
    "$BELTDYN" check "$tmp/$m.yaml" >"$tmp/out_$m" 2>"$tmp/err" \
        || bad "check $m" "$(cat "$tmp/err")"
    if ! grep -q "turns .* rad\|^warning: the idlers" "$tmp/out_$m"; then
        ok "$m: nothing said"
    else
        bad "$m" "$(grep 'turns\|^warning' "$tmp/out_$m")"
    fi
done
tally
