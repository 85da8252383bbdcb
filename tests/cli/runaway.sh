#!/usr/bin/env bash
# A runaway stops the run (issue 10 item 7, src/sim/bounds.c): a torque
# drive on a frictionless pulley spins up alone; `beltdyn run` exits 1 and
# says on stderr when (t =), where (pulley 'head', its centre) and why
# (surface speed beyond the 50 m/s bound); summary.json says "failed".
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/runaway.yaml" <<'YAML'
name: runaway torque drive
gravity: 0
belt: {mass_per_length: 10, axial_stiffness: 1.0e6, initial_tension: 5000}
pulleys:
  - name: head
    x: 10
    y: 0
    radius: 0.3
    wrap: cw
    mass: 100
    friction: {static: 0, dynamic: 0}
    drive: {control: torque, torque: [[0, 0], [0.05, 50000]]}
  - {name: tail, x: 0, y: 0, radius: 0.3, wrap: cw, mass: 100}
simulation: {duration: 2}
YAML
"$BELTDYN" run "$tmp/runaway.yaml" -o "$tmp/out" --quiet >"$tmp/stdout" 2>"$tmp/stderr"
rc=$?
. "$(dirname "$0")/lib/tally.sh"
[ $rc -eq 1 ] && ok "exit code 1" || bad "exit code" "$rc, want 1"
msg=$(cat "$tmp/stderr")
if echo "$msg" | grep -q "at t = [0-9.]* s" && echo "$msg" | grep -q "pulley 'head' at (x = 10.000, y = 0.000)" \
    && echo "$msg" | grep -q "surface speed .* beyond the bound of 50 m/s"; then
    ok "stderr says when, where and why: $msg"
else
    bad "stderr" "$msg"
fi
if python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); assert s["status"] == "failed" and s["duration_s"] < 0.2' \
    "$tmp/out/summary.json" 2>/dev/null; then ok "summary.json: failed, early"
else bad "summary.json" "missing, or not failed early"; fi
tally
