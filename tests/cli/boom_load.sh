#!/usr/bin/env bash
# Boom models through the command (boom-format.md; cli.md "Exit codes and
# errors"): a file whose top level has `boom` goes to the boom's loader.
# tests/data/boom_ok.yaml passes `check` (exit 0, its description on
# stdout, no error); every bad_boom_*.yaml makes
# `check` and `run -o DIR` exit 2 with exactly the expected
# "FILE:LINE:COL: error: PATH: MESSAGE" line (and no other) on stderr, and
# `run` writes nothing. static, study and cases refuse a boom with exit 2.
# One line per case, then `N passed, M failed`.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/tally.sh"

"$BELTDYN" check "$DATA/boom_ok.yaml" >"$tmp/ok.out" 2>"$tmp/ok.err"
rc=$?
if [ $rc -eq 0 ] && [ -s "$tmp/ok.out" ] && ! grep -q ": error:" "$tmp/ok.err"; then
    ok "boom_ok.yaml: check exits 0"
else
    bad "boom_ok.yaml" "check exit $rc (want 0, a description, no error): $(cat "$tmp/ok.err")"
fi

# refused LABEL WANT OUT COMMAND...: exit 2, stderr exactly WANT, nothing
# written into OUT (when given)
refused() {
    local label=$1 want=$2 out=$3 err rc why=""
    shift 3
    err=$("$BELTDYN" "$@" 2>&1 >/dev/null)
    rc=$?
    [ $rc -eq 2 ] || why="exit $rc, want 2; "
    [ "$err" = "$want" ] || why="${why}stderr is not the one line '$want'; "
    if [ -n "$out" ] && [ -e "$out" ] && [ -n "$(find "$out" -mindepth 1)" ]; then
        why="${why}wrote into $out; "
    fi
    if [ -z "$why" ]; then ok "$label"; else bad "$label" "${why}stderr: $err"; fi
}

# case_bad FILE LINE:COL:MESSAGE: check and run refuse $DATA/FILE with it
case_bad() {
    local f="$DATA/$1" out="$tmp/out_${1%.yaml}"
    refused "$1 (check)" "$f:$2" "" check "$f"
    refused "$1 (run)" "$f:$2" "$out" run "$f" -o "$out"
}

case_bad bad_boom_missing_sections.yaml \
    "2:1: error: boom: missing required key 'sections'"
case_bad bad_boom_one_section.yaml \
    "9:5: error: boom.sections: expected a list of at least 2 entries, got 1"
case_bad bad_boom_unknown_key.yaml \
    "17:5: error: boom.pads: unknown key 'colour'"
case_bad bad_boom_stroke_overlap.yaml \
    "18:3: error: boom.stroke: the stroke reaches 12 m at t = 24 s, beyond the 9.7 m that section 1 allows section 2 (its length 10 m less the pad width 0.3 m)"
case_bad bad_boom_table_start.yaml \
    "19:14: error: boom.stroke.profile: the table's stroke at t = 0 is 1.5 m, not the initial stroke 2 m"
case_bad bad_boom_belt.yaml \
    "2:1: error: belt: a boom model has no belt, pulleys or profile"
case_bad bad_boom_attach_offset.yaml \
    "9:13: error: boom.luffing_cylinder.attach: expected s in (0.956, 10.956] (along section 1's axis from the pivot: where section 1 is), got 0.5"
case_bad bad_boom_wrong_type.yaml \
    "10:64: error: boom.sections[1].bending_stiffness: expected a number > 0, got 'stiff'"

# what takes only a conveyor refuses a boom, writing nothing
only_conveyor() { # label args...
    local label=$1 rc
    shift
    "$BELTDYN" "$@" >"$tmp/c.out" 2>"$tmp/c.err"
    rc=$?
    if [ $rc -eq 2 ] && grep -qF "takes a conveyor model, not a boom" "$tmp/c.err"; then
        ok "$label refuses a boom"
    else
        bad "$label" "exit $rc (want 2 and a message): $(cat "$tmp/c.err")"
    fi
}
only_conveyor static static "$DATA/boom_ok.yaml"
only_conveyor study study "$DATA/boom_ok.yaml" -o "$tmp/study" --quiet
only_conveyor cases cases "$DATA/boom_ok.yaml" -o "$tmp/cases" --quiet
if [ -e "$tmp/study" ] || [ -e "$tmp/cases" ]; then bad "study, cases" "wrote a directory"
else ok "study, cases wrote nothing"; fi

tally
