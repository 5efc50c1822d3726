#!/usr/bin/env bash
# envcrust set-up: install missing Debian packages (idempotent), build, then
#   run   - run the main job on a built-in example (default)
#   test  - run the whole test suite, then install into a temporary prefix and build and run
#           examples/cpp against the installed package, then fuzz each reader for 10 s when
#           clang-14 and libclang-rt-14-dev are installed (what .ci/run calls)
#   build - only build
set -euo pipefail
mode="${1:-run}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ENVCRUST_BUILD_DIR:-$root/build}"
jobs="${ENVCRUST_JOBS:-2}"

packages=(cmake ninja-build g++ pkg-config libcgal-dev libeigen3-dev libtbb-dev libboost-dev
          libgmp-dev libmpfr-dev libcli11-dev nlohmann-json3-dev libgtest-dev libpng-dev
          pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest
          libembree-dev libfreetype-dev fonts-dejavu-core nodejs chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# npm installs the HTML report's three.js; Debian's nodejs comes without it (other builds of
# nodejs bring their own, which the Debian package would conflict with).
command -v npm >/dev/null || missing+=(npm)
if ((${#missing[@]})); then
  echo "setup: installing missing Debian packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The HTML report (--html) embeds three.js at build time, taken from npm at the version
# third_party/package.json pins; without it envcrust builds without --html.
three_pinned="$(node -p "require(process.argv[1]).dependencies.three" "$root/third_party/package.json")"
three_installed="$(node -p "require(process.argv[1]).version" "$root/third_party/node_modules/three/package.json" 2>/dev/null || true)"
if [ "$three_installed" != "$three_pinned" ]; then
  echo "setup: installing three.js $three_pinned with npm into third_party/node_modules"
  npm ci --prefix "$root/third_party" --ignore-scripts --no-audit --no-fund --loglevel=error ||
    echo "setup: npm could not install three.js: envcrust is built without --html" >&2
fi

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$jobs"

case "$mode" in
  build) ;;
  run)
    out="$root/out"
    mkdir -p "$out"
    # The main job: reconstruct the trefoil ribbon (two knotted boundary curves) from 10k
    # samples through its envelope, then report topology, knots, linking and distances.
    "$build/envcrust" reconstruct builtin:trefoil-ribbon -n 10000 --seed 1 \
      -o "$out/trefoil.ply" --envelope-out "$out/trefoil_envelope.ply" \
      --report "$out/trefoil_report.json"
    ;;
  test)
    ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 600
    bash "$root/scripts/test_install.sh" "$build"
    # A short fuzzing pass over every reader (docs/fuzzing.md); skipped without Clang's libFuzzer.
    bash "$root/scripts/fuzz.sh" --seconds "${ENVCRUST_FUZZ_SECONDS:-10}" --if-available
    ;;
  *) echo "usage: scripts/setup.sh [run|test|build]" >&2; exit 2 ;;
esac
