#!/usr/bin/env bash
# Fuzz every file reader with libFuzzer (ASan + UBSan) for a while (docs/fuzzing.md).
#   scripts/fuzz.sh [--seconds N] [--runs N] [--if-available] [READER ...]
# Builds the harnesses of fuzz/ with Clang in build-fuzz (ENVCRUST_FUZZ_BUILD_DIR), runs each
# for N seconds (default 60) on a copy of its seed corpus (fuzz/corpus/READER stays as
# committed), prints per reader the executions and the outcome, and exits 1 on any crash,
# leak, hang or out-of-memory, naming the reproducer saved under build-fuzz/crashes/.
# --runs N: stop each reader after N executions instead (with --seconds too: whichever comes first).
# --if-available: exit 0 with a message when Clang or libFuzzer is missing (the test command).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ENVCRUST_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${ENVCRUST_JOBS:-2}"
all_readers=(ply off obj stl xyz pts csv iges nurbs_json polyline balls las)
seconds=60
seconds_given=0
runs=""
if_available=0
readers=()
while (($#)); do
  case "$1" in
    --seconds) seconds="${2:?--seconds needs a number}"; seconds_given=1; shift 2 ;;
    --runs) runs="${2:?--runs needs a number}"; shift 2 ;;
    --if-available) if_available=1; shift ;;
    -h|--help) sed -n '2,9p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz: unknown option $1" >&2; exit 2 ;;
    *) readers+=("$1"); shift ;;
  esac
done
[[ "$seconds" =~ ^[0-9]+$ ]] && ((seconds > 0)) || { echo "fuzz: --seconds wants a whole number > 0, got '$seconds'" >&2; exit 2; }
[ -z "$runs" ] || { [[ "$runs" =~ ^[0-9]+$ ]] && ((runs > 0)); } || { echo "fuzz: --runs wants a whole number > 0, got '$runs'" >&2; exit 2; }
# With --runs alone the executions are the only limit, not the 60 s default.
limits=(-max_total_time="$seconds")
if [ -n "$runs" ]; then
  limits=(-runs="$runs")
  ((seconds_given)) && limits+=(-max_total_time="$seconds")
fi
((${#readers[@]})) || readers=("${all_readers[@]}")
for r in "${readers[@]}"; do
  [[ " ${all_readers[*]} " == *" $r "* ]] || { echo "fuzz: unknown reader '$r' (one of: ${all_readers[*]})" >&2; exit 2; }
done

# Clang with its libFuzzer runtime (Debian: clang-14 and libclang-rt-14-dev).
cxx="${ENVCRUST_FUZZ_CXX:-}"
if [ -z "$cxx" ]; then
  for candidate in clang++-14 clang++; do
    command -v "$candidate" >/dev/null && { cxx="$candidate"; break; }
  done
fi
missing=""
if [ -z "$cxx" ] || ! command -v "$cxx" >/dev/null; then
  missing="no ${cxx:-clang++} (Debian: apt-get install clang-14 libclang-rt-14-dev)"
elif [ ! -f "$("$cxx" -print-runtime-dir 2>/dev/null)/libclang_rt.fuzzer-x86_64.a" ] &&
     [ ! -f "$("$cxx" -print-file-name=libclang_rt.fuzzer-x86_64.a 2>/dev/null)" ]; then
  missing="$cxx has no libFuzzer runtime (Debian: apt-get install libclang-rt-14-dev)"
fi
if [ -n "$missing" ]; then
  if ((if_available)); then
    echo "fuzz: skipped: $missing"
    exit 0
  fi
  echo "fuzz: $missing" >&2
  exit 2
fi

# -O1 with line tables: fast to build, assertions kept (no NDEBUG), readable stack traces.
start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DENVCRUST_FUZZ=ON \
  -DENVCRUST_BUILD_TESTS=OFF -DENVCRUST_BUILD_BENCH=OFF >/dev/null
nice -n 10 cmake --build "$build" -j "$jobs" --target envcrust_fuzzers
echo "fuzz: harnesses built in $(($(date +%s) - start)) s"

# The corpus copies in memory when possible (libFuzzer writes each new input there).
scratch="${TMPDIR:-/tmp}"
[ -d /dev/shm ] && [ -w /dev/shm ] && scratch=/dev/shm
work="$(mktemp -d "$scratch/envcrust-fuzz.XXXXXX")"
trap 'rm -rf "$work"' EXIT
crashes="$build/crashes"
logs="$build/fuzz-logs"
mkdir -p "$crashes" "$logs"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
failed=()
printf '%-11s %12s %8s %8s  %s\n' reader executions exec/s seconds outcome
for r in "${readers[@]}"; do
  dict="$root/fuzz/dict/$r.dict"
  case "$r" in xyz|pts|csv) dict="$root/fuzz/dict/points.dict" ;; esac
  cp -r "$root/fuzz/corpus/$r" "$work/$r"
  mkdir -p "$crashes/$r"
  log="$logs/$r.log"
  status=0
  reader_start=$(date +%s)
  # -timeout: one input over 10 s is a hang (libFuzzer counts wall time: on a machine busy
  # with other work a reader under nice can be starved past that on an input it runs in 0.2 s,
  # so long runs beside other jobs raise it with ENVCRUST_FUZZ_TIMEOUT); -rss_limit_mb also
  # caps a single allocation.
  nice -n 10 "$build/fuzz/${r}_fuzz" "${limits[@]}" -timeout="${ENVCRUST_FUZZ_TIMEOUT:-10}" -rss_limit_mb=2048 \
    -dict="$dict" -artifact_prefix="$crashes/$r/" -print_final_stats=1 "$work/$r" >"$log" 2>&1 || status=$?
  executed=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  if ((status == 0)); then
    outcome="ok"
  else
    artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)
    kind=$(grep -m1 -oE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer): [a-z-]+|runtime error|deadly signal|timeout|out-of-memory' "$log" || true)
    outcome="FAILED (${kind:-exit $status}): reproducer ${artifact:-none}, log $log"
    failed+=("$r")
  fi
  printf '%-11s %12s %8s %8s  %s\n' "$r" "${executed:-?}" "${rate:-?}" "$(($(date +%s) - reader_start))" "$outcome"
done
limit="${seconds} s"
[ -n "$runs" ] && limit="$runs executions$( ((seconds_given)) && echo " or ${seconds} s")"
echo "fuzz: $((${#readers[@]} - ${#failed[@]})) of ${#readers[@]} readers clean after ${limit} each; total $(($(date +%s) - start)) s"
if ((${#failed[@]})); then
  echo "fuzz: findings in: ${failed[*]} (replay one: $build/fuzz/READER_fuzz FILE)" >&2
  exit 1
fi
