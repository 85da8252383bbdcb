#!/usr/bin/env bash
# `beltdyn study` in parallel (issue 16) on a 6-case start study of a small
# conveyor (3 curves x 2 delays, each ~5 s simulated):
# - -j 2 writes the serial (-j 1) table, bit for bit but the wall clock;
# - under mpirun -np 1 (when there is one) the cases run in the one rank,
#   no workers forked, and write the serial table;
# - a study killed (-9) after some cases completed leaves no worker
#   behind; --resume keeps the completed cases (their case.json untouched)
#   and the final table is the serial one;
# - SIGINT stops all workers: exit 130, the table holds the finished cases
#   (valid CSV, statuses completed or interrupted), no worker left;
# - a case.json that cannot be written is said, naming the case;
# - a case whose directory path is too long fails, saying so;
# - a non-empty directory that holds no study is refused (exit 2) unless
#   --force.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../data" && pwd)}"
work=$(mktemp -d)
pid=""
trap '[ -n "$pid" ] && kill -9 "$pid" 2>/dev/null; rm -rf "$work"' EXIT
. "$(dirname "$0")/lib/tally.sh"
. "$(dirname "$0")/lib/same_table.sh"

model="$DATA/study_small.yaml"
cases=(--curves linear,harrison,s-curve --times 1 --delays 0,0.5 --after 4)

# wait (at most 60 s) until DIR holds at least N case.json; 0 when it does
wait_cases() { # dir n
    for _ in $(seq 3000); do
        [ "$(find "$1" -name case.json 2>/dev/null | wc -l)" -ge "$2" ] && return 0
        kill -0 "$pid" 2>/dev/null || return 1
        sleep 0.02
    done
    return 1
}
# no process is left running the study of DIR
no_workers() { # dir
    for _ in $(seq 50); do
        pgrep -f -- "-o $1( |$)" >/dev/null || return 0
        sleep 0.1
    done
    return 1
}

# the serial table, then -j 2
if "$BELTDYN" study "$model" -o "$work/serial" "${cases[@]}" -j 1 >"$work/serial.out" 2>&1; then
    ok "serial study (-j 1) completed"
else
    bad "serial study" "exit $?: $(tail -3 "$work/serial.out")"
fi
if "$BELTDYN" study "$model" -o "$work/j2" "${cases[@]}" -j 2 >"$work/j2.out" 2>&1; then
    ok "-j 2 study completed"
else
    bad "-j 2 study" "exit $?: $(tail -3 "$work/j2.out")"
fi
if grep -q "2 worker processes" "$work/j2.out"; then ok "-j 2 ran 2 worker processes"
else bad "-j 2" "did not say it ran 2 worker processes: $(head -1 "$work/j2.out")"; fi
if msg=$(same_table "$work/serial" "$work/j2"); then ok "-j 2 table = serial table"
else bad "-j 2 table" "$msg"; fi

# under `mpirun -np 1` (a world of one rank) the cases run in the rank's
# own process, whatever -j says: it used to fork -j workers after
# MPI_Init, which Open MPI does not support. Only where mpirun is and the
# build has MPI (a build without it refuses to run under mpirun).
if command -v mpirun >/dev/null; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader \
        ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
        timeout 120 mpirun -np 1 "$BELTDYN" study "$model" -o "$work/np1" "${cases[@]}" -j 2 \
        >"$work/np1.out" 2>&1
    rc=$?
    if grep -q "built without MPI" "$work/np1.out"; then
        ok "mpirun -np 1: not checked, this beltdyn has no MPI"
    elif [ $rc -eq 0 ] && grep -q ", 1 MPI rank$" "$work/np1.out" \
        && msg=$(same_table "$work/serial" "$work/np1"); then
        ok "mpirun -np 1 -j 2: one rank, no workers, the serial table"
    else
        bad "mpirun -np 1" "exit $rc: $(head -3 "$work/np1.out") ${msg:-}"
    fi
fi

# killed after 2 cases, then resumed
"$BELTDYN" study "$model" -o "$work/k" "${cases[@]}" -j 2 >"$work/k.out" 2>&1 &
pid=$!
if wait_cases "$work/k" 2; then
    kill -9 "$pid"
    wait "$pid" 2>/dev/null
    pid=""
    done_before=$(find "$work/k" -name case.json | wc -l)
    if [ "$done_before" -lt 6 ]; then ok "killed with $done_before of 6 cases complete"
    else bad "kill" "all 6 cases were complete before the kill"; fi
    if no_workers "$work/k"; then ok "no worker left after the kill"
    else bad "kill" "worker processes still running: $(pgrep -af -- "-o $work/k" | head -3)"; fi
    inodes_before=$(find "$work/k" -name case.json -exec stat -c '%n %i %Y' {} + | sort)
    if "$BELTDYN" study "$model" -o "$work/k" "${cases[@]}" -j 2 --resume >"$work/r.out" 2>&1
    then ok "resumed study completed"
    else bad "resume" "exit $?: $(tail -3 "$work/r.out")"; fi
    if grep -q "($done_before complete before, $((6 - done_before)) to run)" "$work/r.out"
    then ok "resume kept the $done_before complete cases"
    else bad "resume" "did not keep $done_before cases: $(head -1 "$work/r.out")"; fi
    kept=$(find "$work/k" -name case.json -exec stat -c '%n %i %Y' {} + | sort \
           | grep -cxF -f <(echo "$inodes_before"))
    if [ "$kept" -eq "$done_before" ]; then ok "their case.json untouched"
    else bad "resume" "$kept of $done_before case.json untouched"; fi
    if msg=$(same_table "$work/serial" "$work/k"); then ok "resumed table = serial table"
    else bad "resumed table" "$msg"; fi
else
    bad "kill" "no case completed within 60 s (or the study ended): $(tail -3 "$work/k.out")"
    pid=""
fi

# SIGINT once a case has completed
"$BELTDYN" study "$model" -o "$work/i" "${cases[@]}" -j 2 >"$work/i.out" 2>"$work/i.err" &
pid=$!
if wait_cases "$work/i" 1 && kill -INT "$pid" 2>/dev/null; then
    wait "$pid"
    rc=$?
    pid=""
    if [ $rc -eq 130 ]; then ok "SIGINT: exit 130"
    else bad "SIGINT" "exit $rc, want 130: $(tail -2 "$work/i.err")"; fi
    if no_workers "$work/i"; then ok "SIGINT: no worker left"
    else bad "SIGINT" "worker processes still running"; fi
    if python3 - "$work/i" <<'PY'
import csv, json, sys
d = sys.argv[1]
rows = list(csv.reader(open(d + "/study.csv")))
head, body = rows[0], rows[1:]
assert all(len(r) == len(head) for r in body), "ragged rows"
st = [r[head.index("status")] for r in body]
assert st.count("completed") >= 1, st
assert set(st) <= {"completed", "interrupted"}, st
assert len(json.load(open(d + "/study.json"))["cases"]) == len(body)
PY
    then ok "SIGINT: the table holds the finished cases"
    else bad "SIGINT" "study.csv/study.json not a valid partial table"; fi
else
    bad "SIGINT" "no case completed before the study ended"
    pid=""
fi

# a case.json that cannot be written (a directory, not empty, in its
# place) is said with the case's name, in this process and from a worker;
# the study still completes (it used to be silent, and --resume reran it)
for j in 1 2; do
    mkdir -p "$work/nw$j/linear_T1_d0/case.json" && touch "$work/nw$j/linear_T1_d0/case.json/x"
    "$BELTDYN" study "$model" -o "$work/nw$j" --curves linear --times 1 --delays 0,0.5 \
        --after 1 --force -j $j >"$work/nw.out" 2>"$work/nw.err"
    rc=$?
    if [ $rc -eq 0 ] && grep -q "^case linear_T1_d0: warning: cannot write case.json.*Is a directory" \
        "$work/nw.err" && [ "$(grep -c "cannot write" "$work/nw.err")" -eq 1 ]; then
        ok "-j $j: a case.json that cannot be written is said, naming the case"
    else
        bad "-j $j: case.json not written" "exit $rc: $(head -c 400 "$work/nw.err")"
    fi
done

# a case's directory path too long for the run's files: the case fails
# saying so, and nothing is written under a name cut short (it was)
d200=$(printf 'd%.0s' $(seq 200))
long="$work/$d200/$d200/$d200/$d200/$d200"
mkdir -p "$long"
"$BELTDYN" study "$model" -o "$long/s" --curves linear --times 1 --delays 0 --after 1 -j 1 \
    >"$work/long.out" 2>"$work/long.err"
rc=$?
if [ $rc -eq 1 ] && grep -q "path too long" "$work/long.err" \
    && [ "$(ls "$long/s" | tr '\n' ' ')" = "study.csv study.json " ] \
    && grep -Eq "^linear_T1_d0,([^,]*,){4}(bad input|failed)," "$long/s/study.csv"; then
    ok "a path too long for a case's files: the case fails saying so, nothing cut short"
else
    bad "path too long" "exit $rc: $(ls "$long/s" | head -5) $(head -c 300 "$work/long.err")"
fi

# a non-empty directory that is not a study's
mkdir -p "$work/other" && echo x >"$work/other/notes.txt"
"$BELTDYN" study "$model" -o "$work/other" --curves linear --times 1 --delays 0 >"$work/o.out" 2>&1
rc=$?
if [ $rc -eq 2 ] && grep -q "force" "$work/o.out" && [ ! -e "$work/other/study.csv" ]; then
    ok "a non-empty directory without a study is refused (exit 2)"
else
    bad "refuse" "exit $rc: $(tail -2 "$work/o.out")"
fi
if "$BELTDYN" study "$model" -o "$work/other" --curves linear --times 1 --delays 0 --force \
    >"$work/o.out" 2>&1 && [ -s "$work/other/study.csv" ]; then
    ok "--force writes into it"
else
    bad "--force" "$(tail -2 "$work/o.out")"
fi
tally
