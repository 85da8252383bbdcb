#!/usr/bin/env bash
# The installed library is usable: install BUILD into a temporary prefix,
# build examples/api out of tree against it with pkg-config, run it on
# examples/vertical_loop.yaml for 1 s and check its output.
#
#     tests/api/build_api_example.sh [BUILD]     (default: build)
#
# Environment (ctest sets them, see tests/CMakeLists.txt): API_CC the C
# compiler, API_CMAKE the cmake command, API_EXTRA_FLAGS extra compile and
# link flags (-fsanitize=... when the library is instrumented; without it,
# read from BUILD/CMakeCache.txt). The last line is "N passed, M failed".
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
case $build in /*) ;; *) [ -d "$build" ] || build=$root/$build ;; esac

fail() {
    echo "FAIL: $*" >&2
    echo "0 passed, 1 failed"
    exit 1
}

[ -f "$build/CMakeCache.txt" ] || fail "$build is not a configured build directory"
cc=${API_CC:-cc}
cmake_cmd=${API_CMAKE:-cmake}
if [ -z "${API_EXTRA_FLAGS+set}" ]; then
    API_EXTRA_FLAGS=
    if grep -q '^BD_SANITIZE:BOOL=ON$' "$build/CMakeCache.txt"; then
        API_EXTRA_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
    fi
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/beltdyn_api.XXXXXX") || fail "mktemp"
trap 'rm -rf "$tmp"' EXIT

"$cmake_cmd" --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 \
    || { cat "$tmp/install.log" >&2; fail "cmake --install $build"; }
for f in lib/libbeltdyn.a lib/pkgconfig/beltdyn.pc include/beltdyn/model.h \
         include/beltdyn/sim.h bin/beltdyn; do
    [ -e "$tmp/prefix/$f" ] || fail "not installed: $f"
done

cp -R "$root/examples/api" "$tmp/api" || fail "copy examples/api"
PKG_CONFIG_PATH="$tmp/prefix/lib/pkgconfig" \
    make -C "$tmp/api" CC="$cc" EXTRA_FLAGS="$API_EXTRA_FLAGS" >"$tmp/make.log" 2>&1 \
    || { cat "$tmp/make.log" >&2; fail "building examples/api against the installed beltdyn"; }

"$tmp/api/run_model" "$root/examples/vertical_loop.yaml" 1 >"$tmp/out.txt" 2>"$tmp/err.txt"
status=$?
cat "$tmp/out.txt"
cat "$tmp/err.txt" >&2
[ "$status" -eq 0 ] || fail "run_model exited with $status"
grep -Eq '^peak tension: [1-9][0-9.]* N' "$tmp/out.txt" || fail "no peak tension in the output"
# the run stops at the step nearest to 1 s (within half a time step)
awk '/^time step:/ { dt = $3 } /^ran to t =/ { t = $5 }
     END { exit !(dt > 0 && t >= 1 - dt && t <= 1 + dt) }' "$tmp/out.txt" \
    || fail "did not run to t = 1 s"
echo "1 passed, 0 failed"
