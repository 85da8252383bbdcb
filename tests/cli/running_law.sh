#!/usr/bin/env bash
# `check` prints the steady running force of the model's own resistance
# law (sim/running_law.c) at the drives' speed, against a hand count:
# two 0.5 m pulleys 100 m apart, level, so both spans are 100 m between
# their tangent points. The carry idlers every 1 m stand at 1 … 99 m, the
# return ones evenly at the spacing nearest 3 m, 100/33 m (32 idlers).
# Each idler carries the belt between the midpoints to its neighbours, the
# pulleys the half gaps at the ends, so the idlers of a span carry
# (span − spacing): 99 m and 100 − 100/33 m. With m′ = 20 kg/m, rr = 0.02,
# g = 9.81, the idler term is 0.02·9.81·20·(99 + 96.9697) = 768.92 N;
# material 30 kg/m fed at the tail end of the carry (the whole carry span
# loaded) adds rr·g·30·99 = 582.71 N to the idlers, and its acceleration
# at the feed m′_L·v² = 30·2² = 120 N. Tail bearing_damping 8 N·m·s on
# 0.5 m: 8/0.25·2 = 64 N. Expected 768.92 + 582.71 + 120 + 64 = 1535.63 N.
# Printed to 4 digits: 1536 N.
. "$(dirname "$0")/lib/setup.sh"
cat >"$tmp/law.yaml" <<'YAML'
name: two-pulley law check
gravity: 9.81
belt: {mass_per_length: 20, axial_stiffness: 5.0e6}
pulleys:
  - name: head
    x: 100
    y: 0
    radius: 0.5
    wrap: cw
    drive: {control: speed, speed: 2.0, start: {curve: linear, time: 5}}
  - name: tail
    x: 0
    y: 0
    radius: 0.5
    wrap: cw
    bearing_damping: 8
    takeup: {type: constant_force, force: 20000, axis: [-1, 0]}
idlers:
  - {span: tail, spacing: 1.0, rolling_resistance: 0.02}
  - {span: head, spacing: 3.0, rolling_resistance: 0.02}
material: {mass_per_length: 30, feed: {span: tail, at: 0.0}}
simulation: {duration: 1}
YAML
"$BELTDYN" check "$tmp/law.yaml" >"$tmp/out" 2>"$tmp/err"
line=$(grep "^steady running force" "$tmp/out")
want="steady running force at 2 m/s by the model's own law: 1536 N (idler rolling resistance 1352 N, lift of the load 0 N, its acceleration at the feed 120 N, pulley bearing_damping 64 N)"
if [ "$line" = "$want" ]; then
    ok "check prints: $line"
else
    bad "running law line" "got: $line / want: $want / $(cat "$tmp/err")"
fi
tally
