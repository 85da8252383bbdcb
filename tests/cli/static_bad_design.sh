#!/usr/bin/env bash
# bad `design` input (unknown standard, negative f, C below 1) is a
# FILE:LINE:COL error with exit code 2 (cli.md, model-format.md)
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
fail=0

probe=$("$BELTDYN" static "$DATA/static_horizontal.yaml" --json 2>&1)
rc=$?
if [ $rc -ne 0 ] && printf '%s' "$probe" | grep -qiE 'unknown|usage'; then
    echo "SKIP: beltdyn static is not wired yet"
    exit 0
fi

bad() { # file key line
    local f="$DATA/$1" err rc
    err=$("$BELTDYN" static "$f" --json 2>&1 >/dev/null)
    rc=$?
    [ $rc -eq 2 ] || { echo "FAIL $1: exit $rc, want 2"; fail=1; }
    printf '%s\n' "$err" | grep -qE "^$f:$3:[0-9]+: error: .*$2" \
        || { echo "FAIL $1: want '$f:$3:COL: error: ...$2...', got: $err"; fail=1; }
}
bad static_bad_standard.yaml 'standard' 7
bad static_bad_f.yaml        '\bf\b'    7
bad static_bad_C.yaml        '\bC\b'    7

[ $fail -eq 0 ] && echo "static_bad_design: ok"
exit $fail
