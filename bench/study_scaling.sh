#!/usr/bin/env bash
# Scaling of `beltdyn study` (issue 16): the same 8-case start study of
# examples/head_drive.yaml (4 curves x start times 4 and 8 s, each run to
# 4 s after its start: 8 and 12 s simulated) at -j 1 and -j 2 back to
# back, then under mpirun -np 2 when there is one, with each table checked
# against the serial one. Prints the wall times and the speed-ups; the
# acceptance figure is -j 2 >= 1.7x on two free cores. Not a test: timing
# depends on what else runs (the load average is printed first).
#   bench/study_scaling.sh [BUILD_DIR]        (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
beltdyn=$build/beltdyn
[ -x "$beltdyn" ] || { echo "study_scaling: $beltdyn not built" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# same_table DIR_A DIR_B: the tables equal but the wall-clock column (by name)
. "$root/tests/cli/lib/same_table.sh"
args=(study "$root/examples/head_drive.yaml" --curves linear,harrison,nordell,s-curve
      --times 4,8 --delays 0 --after 4 --quiet)
echo "cores: $(nproc); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
seconds() { # label command...
    local label=$1 t0 t1
    shift
    t0=$(date +%s.%N)
    # the failure goes to stderr: stdout is the caller's $(...), the time
    "$@" >"$work/$label.out" 2>&1 || {
        echo "$label failed:" >&2
        tail -5 "$work/$label.out" >&2
        exit 1
    }
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }'
}
same() { # dir: its table without the wall-clock column equals the serial one
    same_table "$work/j1" "$1" >&2
}
t1=$(seconds j1 "$beltdyn" "${args[@]}" -o "$work/j1" -j 1)
t2=$(seconds j2 "$beltdyn" "${args[@]}" -o "$work/j2" -j 2)
same "$work/j2" && s2="same table" || s2="TABLE DIFFERS"
echo "8-case study, -j 1: $t1 s"
echo "8-case study, -j 2: $t2 s ($s2)"
awk -v a="$t1" -v b="$t2" 'BEGIN { printf "speed-up -j 2 over -j 1: %.2fx\n", a / b }'
if command -v mpirun >/dev/null; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # two ranks on this machine need no network interfaces (as study_mpi.sh)
    export OMPI_MCA_btl=self,vader
    tm=$(seconds mpi mpirun --oversubscribe -np 2 "$beltdyn" "${args[@]}" -o "$work/mpi")
    same "$work/mpi" && sm="same table" || sm="TABLE DIFFERS"
    echo "8-case study, mpirun -np 2: $tm s ($sm)"
    awk -v a="$t1" -v b="$tm" 'BEGIN { printf "speed-up mpirun -np 2 over -j 1: %.2fx\n", a / b }'
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
