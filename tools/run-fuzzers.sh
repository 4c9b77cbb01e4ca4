#!/usr/bin/env bash
# Runs each libFuzzer target of BUILD for SECONDS, starting from the committed seed corpus
# (tests/fuzz/corpus/TARGET/, read only) plus what earlier runs found (BUILD/fuzz/TARGET/).
# Appends executions and findings to BUILD/fuzz/log.txt; exits 1 if any target found a
# crash, a leak or a hang (the input is in BUILD/fuzz/artifacts/TARGET/).
# Usage: tools/run-fuzzers.sh BUILD SECONDS TARGET...
set -uo pipefail
build=$1 seconds=$2
shift 2
src=$(cd "$(dirname "$0")/.." && pwd)
log=$build/fuzz/log.txt
mkdir -p "$build/fuzz"
# Leaks of the system's libraries (assimp's, on some refused files) are theirs, not findings.
export LSAN_OPTIONS="suppressions=$src/tools/lsan-suppressions.txt${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
for t in "$@"; do
  work=$build/fuzz/$t artifacts=$build/fuzz/artifacts/$t/
  mkdir -p "$work" "$artifacts"
  out=$build/fuzz/$t.out
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: runaway allocation is a finding.
  "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -print_final_stats=1 -artifact_prefix="$artifacts" "$work" "$src/tests/fuzz/corpus/$t" >"$out" 2>&1
  rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out" | grep -o '[0-9]*$' || echo "?")
  found=$(ls "$artifacts" 2>/dev/null | wc -l)
  line="$(date -u +%FT%TZ) $t: ${seconds}s, $execs executions, exit $rc, $found artifact(s) in $artifacts"
  echo "$line" | tee -a "$log"
  if [ "$rc" -ne 0 ]; then
    status=1
    grep -m3 -E 'ERROR|SUMMARY|invariant|runtime error' "$out" || true
  fi
done
exit $status
