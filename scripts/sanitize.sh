#!/usr/bin/env bash
# The unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (g++; docs/fuzzing.md).
#   scripts/sanitize.sh [--modules "io mesh ..."] [-R REGEX] [-L LABEL]
# Builds the test executables of the listed modules (default: all of tests/) in build-asan
# (ENVCRUST_ASAN_BUILD_DIR) and runs them with ctest (default label: unit; -R narrows by name).
# Any sanitizer report fails its test. Suppressions, each with its reason: scripts/sanitizers/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ENVCRUST_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="${ENVCRUST_JOBS:-2}"
modules=""
regex=""
label="unit"
while (($#)); do
  case "$1" in
    --modules) modules="${2:?--modules needs a list}"; shift 2 ;;
    -R) regex="${2:?-R needs a regex}"; shift 2 ;;
    -L) label="${2:?-L needs a label}"; shift 2 ;;
    -h|--help) sed -n '2,6p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "sanitize: unknown argument $1" >&2; exit 2 ;;
  esac
done

flags="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
start=$(date +%s)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DENVCRUST_BUILD_BENCH=OFF >/dev/null
targets=(envcrust_tests)
if [ -n "$modules" ]; then
  targets=()
  for m in $modules; do targets+=("envcrust_${m}_tests"); done
fi
# The CLI tests run the binary: build it when they are asked for.
[[ "$label" == cli || -z "$modules" || " $modules " == *" cli "* ]] && targets+=(envcrust_cli)
nice -n 10 cmake --build "$build" -j "$jobs" --target "${targets[@]}"
echo "sanitize: built in $(($(date +%s) - start)) s"

supp="$root/scripts/sanitizers"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:abort_on_error=1:detect_stack_use_after_return=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
ctest_args=(--output-on-failure -j "$jobs" --timeout 1800 -L "$label")
[ -n "$regex" ] && ctest_args+=(-R "$regex")
# One ctest per module folder: tests of executables not built would fail as *_NOT_BUILT.
dirs=("$build")
if [ -n "$modules" ]; then
  dirs=()
  for m in $modules; do dirs+=("$build/tests/$m"); done
fi
failed=()
for dir in "${dirs[@]}"; do
  nice -n 10 ctest --test-dir "$dir" "${ctest_args[@]}" || failed+=("${dir#"$build"/}")
done
if ((${#failed[@]})); then
  echo "sanitize: failures in: ${failed[*]} (the reports are above); total $(($(date +%s) - start)) s" >&2
  exit 1
fi
echo "sanitize: clean; total $(($(date +%s) - start)) s"
