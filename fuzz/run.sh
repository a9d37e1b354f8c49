#!/usr/bin/env bash
# Builds the libFuzzer harnesses with the fuzz preset and runs each for SECONDS (default 20), or
# for RUNS executions when RUNS is set (RUNS=1000000 fuzz/run.sh 3600). Prints per harness the
# executions, coverage (cov: edges, ft: features), corpus size and findings; exits 1 on any finding
# (crash, property violation, timeout, leak, out of memory). The committed seeds in
# fuzz/corpus/<harness>/ are read, never written: the growing corpus and any crashing input go to
# build/fuzz/corpus/<harness>/ and build/fuzz/findings/<harness>/. Safe to run again.
#   fuzz/run.sh [SECONDS] [HARNESS …]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${1:-20}"
shift || true
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  harnesses=(fuzz_exact_number fuzz_moments fuzz_coefficients fuzz_scheme_word fuzz_scheme_name fuzz_scheme_table)
fi

cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

build=build/fuzz
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"

status=0
printf '%-20s %12s %8s %8s %8s %9s\n' harness executions cov ft corpus findings
for h in "${harnesses[@]}"; do
  corpus="$build/corpus/$h" findings="$build/findings/$h" log="$build/logs/$h.log"
  rm -rf "$findings"
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  limit=(-max_total_time="$seconds")
  [ -n "${RUNS:-}" ] && limit=(-runs="$RUNS")
  set +e
  "$build/fuzz/$h" "$corpus" "fuzz/corpus/$h" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
    -detect_leaks=1 -print_final_stats=1 -artifact_prefix="$findings/" >"$log" 2>&1
  rc=$?
  set -e
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  size=$(find "$corpus" -type f | wc -l)
  found=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  printf '%-20s %12s %8s %8s %8s %9s\n' "$h" "${executions:-?}" "${cov:-?}" "${ft:-?}" "$size" "$found"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1
    echo "  $h: exit status $rc; log $log; inputs in $findings/" >&2
    grep -E 'ERROR|property violated|runtime error' "$log" | head -5 >&2 || true
  fi
done
exit "$status"
