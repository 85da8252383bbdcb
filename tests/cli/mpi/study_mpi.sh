#!/usr/bin/env bash
# `beltdyn study` under `mpirun --oversubscribe -np 2` (issue 16): rank 0
# hands out the cases, both ranks run them, rank 0 writes the table; it is
# the serial table, bit for bit but the wall clock, for a start study and
# for a sweep. Registered only when the build has MPI (tests/CMakeLists.txt);
# MPIEXEC names mpirun.
set -u
: "${BELTDYN:?BELTDYN must name the built beltdyn}"
: "${MPIEXEC:?MPIEXEC must name mpirun}"
DATA="${TEST_DATA:-$(cd "$(dirname "$0")/../../data" && pwd)}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/../lib/tally.sh"
. "$(dirname "$0")/../lib/same_table.sh"

# root may run mpirun in a container (Open MPI refuses it otherwise)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# no network interfaces are needed for two ranks on this machine
export OMPI_MCA_btl=self,vader OMPI_MCA_rmaps_base_oversubscribe=1
# Under the sanitizers the ranks leave Open MPI's own allocations behind
# (MPI_Finalize does not free all of MPI_Init's, partly in components it
# has unloaded, so no suppression can name them): leak checking is off for
# the ranks only; the same study code is leak-checked by study_parallel.sh
mpi() {
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
        timeout 120 "$MPIEXEC" --oversubscribe -np 2 "$@"
}

start=(study "$DATA/study_small.yaml" --curves linear,s-curve --times 1 --delays 0,0.5 --after 1)
sweep=(study "$DATA/sweep_small.yaml" --vary pulleys.head.drive.start.time=1:3:3
       --vary pulleys.tail.takeup.mass=600:900:2)
declare -A cases=([start]=4 [sweep]=6)   # 2 curves x 2 delays; 3 x 2 grid
for what in start sweep; do
    declare -n args=$what
    if "$BELTDYN" "${args[@]}" -o "$work/$what.serial" -j 1 >"$work/$what.serial.out" 2>&1
    then ok "$what: serial study completed"
    else bad "$what: serial" "exit $?: $(tail -3 "$work/$what.serial.out")"; fi
    if mpi "$BELTDYN" "${args[@]}" -o "$work/$what.mpi" >"$work/$what.mpi.out" 2>&1
    then ok "$what: mpirun -np 2 study completed"
    else bad "$what: mpirun" "exit $?: $(tail -5 "$work/$what.mpi.out")"; fi
    if grep -q "2 MPI ranks" "$work/$what.mpi.out"; then ok "$what: ran on 2 ranks"
    else bad "$what: ranks" "$(head -3 "$work/$what.mpi.out")"; fi
    # rank 0 printed a row for every case, whichever rank ran it
    if [ "$(grep -c "^[A-Za-z_0-9.-]* \+[0-9]" "$work/$what.mpi.out")" -ge "${cases[$what]}" ]; then
        ok "$what: every case reported"
    else bad "$what: rows" "$(cat "$work/$what.mpi.out")"; fi
    if msg=$(same_table "$work/$what.serial" "$work/$what.mpi"); then
        ok "$what: mpirun table = serial table"
    else bad "$what: table" "$msg"; fi
done
tally
