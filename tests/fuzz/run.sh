#!/usr/bin/env bash
# Fuzz the model loaders and `check` (fuzz_model, built by -DBD_FUZZ=ON) for
# SECONDS over a copy of the committed corpus tests/fuzz/corpus, which is
# never written. Fails on any crash, hang (> 10 s an input), leak, sanitizer
# report or out-of-memory; the input that did it is kept and named.
#
#   run.sh FUZZER SECONDS [WORKDIR]
#
# WORKDIR (default: a temporary folder, removed when the run passes) receives
# corpus/ (the committed corpus and what the run added) and artifacts/.
# ctest runs this in build-fuzz (tests/fuzz/CMakeLists.txt); scripts/fuzz
# builds and runs it by hand.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
fuzzer=${1:?usage: run.sh FUZZER SECONDS [WORKDIR]}
seconds=${2:?usage: run.sh FUZZER SECONDS [WORKDIR]}
work=${3:-}
if [ -z "$work" ]; then
  work=$(mktemp -d)
  keep=0
else
  mkdir -p "$work"
  keep=1
fi
mkdir -p "$work/corpus" "$work/artifacts"
cp "$here"/corpus/* "$work/corpus/"

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions="$here/../lsan.supp"
set +e
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -dict="$here/yaml.dict" -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus" 2>"$work/fuzz.log"
rc=$?
set -e
grep -E '^(#[0-9]+ +DONE|stat::|Done )' "$work/fuzz.log" || true
found=$(find "$work/artifacts" -type f | head -n 20)
if [ $rc -ne 0 ] || [ -n "$found" ]; then
  tail -n 60 "$work/fuzz.log"
  echo "fuzz_model: FAILED (exit $rc); log $work/fuzz.log"
  for f in $found; do
    echo "reproduce: $fuzzer $f"
  done
  exit 1
fi
echo "fuzz_model: ${seconds} s, no crash, hang, leak or sanitizer report"
[ "$keep" -eq 1 ] || rm -rf "$work"
