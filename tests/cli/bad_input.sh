#!/usr/bin/env bash
# Bad input (cli.md "Exit codes and errors", issue 2 "Bad input"): every bad
# model in tests/data/bad_*.yaml makes `beltdyn check` and `beltdyn run -o DIR`
# exit 2 with a line `FILE:LINE:COL: error: ...` on stderr that names the key
# at the line where the problem is, and `run` writes nothing. Usage errors and
# a missing model file exit 2 too. One line per case, then `N passed, M failed`.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/tally.sh"

# does stderr text $1 hold a line "$2:LINE:COL: error: ...KEY..." with LINE
# matching the extended regex $3 and the message matching the regex $4?
has_error_line() {
    local text=$1 file=$2 line_re=$3 key_re=$4 l rest
    while IFS= read -r l; do
        case "$l" in
        "$file:"*)
            rest=${l#"$file:"}
            if printf '%s\n' "$rest" | grep -qE "^($line_re):[0-9]+: error: .*($key_re)"; then
                return 0
            fi
            ;;
        esac
    done <<<"$text"
    return 1
}

# the small valid two-pulley model the bad_*.yaml files are variations of:
# it must pass, so that each bad file fails for its own reason
cat >"$tmp/valid.yaml" <<'EOF'
name: valid
belt:
  mass_per_length: 0.3
  axial_stiffness: 2.0e5
  initial_tension: 500
pulleys:
  - name: a
    x: 0
    y: 0
    radius: 0.1
    wrap: ccw
    drive: {control: speed, speed: 1}
  - name: b
    x: 1.0
    y: 0
    radius: 0.2
    wrap: ccw
simulation:
  duration: 0.01
EOF
"$BELTDYN" check "$tmp/valid.yaml" >/dev/null 2>"$tmp/valid.err"
rc=$?
if [ $rc -eq 0 ]; then ok "valid base model: check exits 0"
else bad "valid base model" "check exit $rc, want 0: $(cat "$tmp/valid.err")"; fi
"$BELTDYN" run "$tmp/valid.yaml" -o "$tmp/valid_out" >/dev/null 2>"$tmp/valid.err"
rc=$?
if [ $rc -eq 0 ] && [ -s "$tmp/valid_out/summary.json" ]; then ok "valid base model: run exits 0 and writes"
else bad "valid base model" "run exit $rc (want 0 and summary.json): $(cat "$tmp/valid.err")"; fi

# case FILE LINE_RE KEY_RE: check and run on $DATA/FILE
case_bad() {
    local name=$1 line_re=$2 key_re=$3 f="$DATA/$1" err rc out n
    for cmd in check run; do
        out="$tmp/out_${name%.yaml}_$cmd"
        if [ $cmd = check ]; then
            err=$("$BELTDYN" check "$f" 2>&1 >/dev/null)
        else
            err=$("$BELTDYN" run "$f" -o "$out" 2>&1 >/dev/null)
        fi
        rc=$?
        local what="$name ($cmd)" why=""
        [ $rc -eq 2 ] || why="exit $rc, want 2; "
        has_error_line "$err" "$f" "$line_re" "$key_re" \
            || why="${why}no line '$f:$line_re:COL: error: ...$key_re...'; "
        if [ $cmd = run ] && [ -e "$out" ]; then
            n=$(find "$out" -mindepth 1 | wc -l)
            [ "$n" -eq 0 ] || why="${why}run wrote $n file(s) in $out; "
        fi
        if [ -z "$why" ]; then ok "$what"; else bad "$what" "${why}stderr: $err"; fi
    done
}

#        file                          line   key named in the message
case_bad bad_malformed.yaml            17     'invalid YAML'
case_bad bad_unknown_key.yaml          7      "colour"
case_bad bad_wrong_type.yaml           5      "axial_stiffness"
case_bad bad_missing_key.yaml          3      "mass_per_length"
case_bad bad_negative_radius.yaml      17     "radius"
case_bad bad_one_pulley.yaml           '7|8'  "pulleys"
# two pulleys whose discs intersect (0.25 m apart, radii 0.1 + 0.2): the
# error belongs to either pulley's entry
case_bad bad_overlap.yaml              '8|14' "pulleys.*overlap|overlap.*pulley"
case_bad bad_overlap_nested.yaml       '8|14' "pulleys.*overlap|overlap.*pulley"
case_bad bad_wrap.yaml                 18     "wrap"
case_bad bad_time_step.yaml            21     "time_step"
# found by the fuzzer: a belt that its weight or its takeup would compress
# at rest is an error (at once), not a crash or minutes of layout
case_bad bad_layout_soft_belt.yaml     5      "belt"
case_bad bad_layout_compressed.yaml    20     "runs through"
# an element longer than half the smallest pulley's circumference: refused
# at the belt (found by CI's fuzz run as a leak on this path)
case_bad bad_element_too_long.yaml     5      "element_length"
# the same on a 0.5 µm bend under a discrete belt with idlers: the idlers'
# turn once laid the belt at that pulley's chord and ran out of memory
# (found by CI's fuzz run at stop 47)
case_bad bad_element_tiny_pulley.yaml  5      "element_length"
# the moving-node belt's own element keys: a count past any int, and the
# key that sets the count named (not element_length, which it does not use)
case_bad bad_mn_wrap_angle.yaml        5      "wrap_element_angle_deg"
case_bad bad_mn_span_element.yaml      4      "span_element_length"
# a belt property so large its highest frequency overflows: no time step
# (the fuzzer reached a NaN step and undefined behaviour in a transmission)
case_bad bad_belt_overflow.yaml        5      "no stable time step"

# usage errors: exit 2
usage_case() { # label args...
    local label=$1 rc
    shift
    "$BELTDYN" "$@" >"$tmp/u.out" 2>"$tmp/u.err"
    rc=$?
    if [ $rc -eq 2 ] && [ -s "$tmp/u.err" ]; then ok "usage: $label"
    else bad "usage: $label" "exit $rc (want 2 with a message on stderr)"; fi
}
usage_case "no subcommand"
usage_case "unknown subcommand" frobnicate "$tmp/valid.yaml"
usage_case "check without a file" check
usage_case "run without a file" run
usage_case "run -o DIR without a file" run -o "$tmp/usage_out"
usage_case "run with an unknown option" run "$tmp/valid.yaml" --bogus -o "$tmp/usage_out"
if [ -e "$tmp/usage_out" ]; then bad "usage: run" "wrote $tmp/usage_out"; else ok "usage: run wrote nothing"; fi

# a model file that does not exist: exit 2, a message naming it, nothing written
for cmd in check run; do
    missing="$tmp/no_such_model.yaml"
    if [ $cmd = check ]; then
        err=$("$BELTDYN" check "$missing" 2>&1 >/dev/null)
    else
        err=$("$BELTDYN" run "$missing" -o "$tmp/missing_out" 2>&1 >/dev/null)
    fi
    rc=$?
    if [ $rc -eq 2 ] && printf '%s' "$err" | grep -qF "$missing" && [ ! -e "$tmp/missing_out" ]; then
        ok "missing model file ($cmd)"
    else
        bad "missing model file ($cmd)" "exit $rc (want 2 and a message naming the file): $err"
    fi
done

tally
