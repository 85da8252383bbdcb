#!/usr/bin/env bash
# SIGINT during `beltdyn run` (cli.md): exit 130, outputs valid up to the last
# complete row (history.csv and tension.csv: every row has the header's column
# count), summary.json written and valid with "status": "interrupted".
# tests/data/long_run.yaml is examples/vertical_loop.yaml with duration 10000:
# it is still running when the signal arrives ~1 s after the start. Bounded:
# the run is killed (-9) after 20 s whatever happens.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
tmp=$(mktemp -d)
. "$(dirname "$0")/lib/sigint_run.sh"
trap 'sigint_cleanup; rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/tally.sh"

out="$tmp/out"
sigint_run "$tmp/run.out" "$tmp/run.err" "$BELTDYN" run "$DATA/long_run.yaml" -o "$out"

if [ $rc -eq 130 ]; then ok "exit code 130"
elif [ $rc -eq 137 ]; then bad "exit code" "killed by the 20 s watchdog: SIGINT did not stop the run"
else bad "exit code" "$rc, want 130; stderr: $(head -c 300 "$tmp/run.err")"; fi

if grep -qi 'interrupt' "$tmp/run.err"; then ok "stderr says the run was interrupted"
else bad "stderr" "no word of the interruption: $(head -c 300 "$tmp/run.err")"; fi

# every row of a CSV file has the header's column count, and the file ends
# with a newline (no half-written row); prints the data row count
complete_csv() { # file
    awk -F, 'NR == 1 { n = NF; next }
             NF != n { printf "row %d has %d columns, header %d\n", NR, NF, n; bad = 1; exit }
             END { if (!bad) print "rows", NR - 1; exit bad }' "$1" || return 1
    [ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ] || { echo "no newline at the end"; return 1; }
}

for f in history.csv tension.csv; do
    if [ ! -s "$out/$f" ]; then
        bad "$f" "missing or empty"
    elif msg=$(complete_csv "$out/$f"); then
        rows=${msg#rows }
        if [ "$rows" -ge 2 ]; then ok "$f: $rows complete rows"
        else bad "$f" "only $rows rows: nothing was simulated before the signal"; fi
    else
        bad "$f" "$msg"
    fi
done

if [ -s "$out/summary.json" ] && python3 - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s.get("status") == "interrupted", "status is %r" % s.get("status")
# the run stopped early: less than the model's 10000 s simulated
assert 0 < s["duration_s"] < 10000, "duration_s %r" % s["duration_s"]
PY
then ok "summary.json valid JSON with \"status\": \"interrupted\" and the time reached"
else bad "summary.json" "missing, invalid, or without \"status\": \"interrupted\""; fi

left=$(find "$out" -mindepth 1 \( -name '*.part*' -o -name '.*' \) 2>/dev/null | head -3)
if [ -z "$left" ]; then ok "no temporary files left"
else bad "temporary files" "$left"; fi

tally
