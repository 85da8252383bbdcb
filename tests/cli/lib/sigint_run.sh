# Sourced by the CLI tests that stop a run with SIGINT (interrupt.sh,
# stabilize.sh); not a test itself (tests/CMakeLists.txt takes cli/*.sh).
# Needs $tmp and the test's ok/bad. After
#     sigint_run OUT ERR beltdyn run MODEL -o DIR
# $rc is the command's exit status and $stop_s the seconds it took to stop
# after the signal, sent 1 s after the start. A watchdog kills the command
# (-9, exit 137) if it outlives 20 s: it polls, so it ends with the command
# and leaves no sleeping child behind. sigint_cleanup (in the EXIT trap)
# kills whatever is left.
sigint_pid=""
sigint_watchdog=""
sigint_cleanup() {
    [ -n "$sigint_watchdog" ] && kill "$sigint_watchdog" 2>/dev/null
    [ -n "$sigint_pid" ] && kill -9 "$sigint_pid" 2>/dev/null
}
sigint_run() { # out err command...
    local out=$1 err=$2
    shift 2
    "$@" >"$out" 2>"$err" &
    sigint_pid=$!
    (
        for _ in $(seq 200); do
            sleep 0.1
            kill -0 "$sigint_pid" 2>/dev/null || exit 0
        done
        kill -9 "$sigint_pid" 2>/dev/null
    ) &
    sigint_watchdog=$!
    sleep 1
    if kill -0 "$sigint_pid" 2>/dev/null; then
        ok "run still going after 1 s"
        kill -INT "$sigint_pid"
    else
        bad "run" "finished before the signal (the model is not long enough)"
    fi
    local t0 t1
    t0=$(date +%s%N)
    wait "$sigint_pid"
    rc=$?
    t1=$(date +%s%N)
    stop_s=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", (b - a) / 1e9 }')
    sigint_pid=""
    kill "$sigint_watchdog" 2>/dev/null
    wait "$sigint_watchdog" 2>/dev/null
    sigint_watchdog=""
}
