#!/usr/bin/env bash
# The installed package, as a user takes it: install a built tree into a temporary prefix,
# build examples/cpp against it with find_package(envcrust), and reconstruct 2,000 samples of
# the built-in hemisphere with that program (a disc: chi 1, one boundary loop), byte for byte
# the mesh `envcrust reconstruct` writes from them (the library's input stage is the CLI's).
#   scripts/test_install.sh [BUILD_DIR]   (default: build; scripts/setup.sh test runs it)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-${ENVCRUST_BUILD_DIR:-$root/build}}"
work="$(mktemp -d "${TMPDIR:-/tmp}/envcrust-install-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT

fail() { echo "install test: FAILED: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" || { cat "$work/install.log" >&2; fail "cmake --install"; }
for f in bin/envcrust include/envcrust/pipeline.h include/envcrust/input.h lib/cmake/envcrust/envcrustConfig.cmake; do
  [ -e "$work/prefix/$f" ] || fail "the install has no $f"
done
cmake -S "$root/examples/cpp" -B "$work/example" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 \
  || { cat "$work/configure.log" >&2; fail "configuring examples/cpp against the installed package"; }
cmake --build "$work/example" >"$work/build.log" 2>&1 || { cat "$work/build.log" >&2; fail "building examples/cpp"; }
"$work/prefix/bin/envcrust" sample hemisphere -n 2000 --seed 1 -q -o "$work/points.xyz" || fail "envcrust sample"
out="$("$work/example/reconstruct_points" "$work/points.xyz" "$work/surface.ply")" || fail "reconstruct_points exited with $?"
echo "$out"
[ -s "$work/surface.ply" ] || fail "reconstruct_points wrote no mesh"
grep -q "chi 1, 1 boundary loops, manifold" <<<"$out" || fail "the hemisphere did not come out as a disc"
"$work/prefix/bin/envcrust" reconstruct "$work/points.xyz" -o "$work/cli.ply" -q || fail "envcrust reconstruct exited with $?"
cmp -s "$work/surface.ply" "$work/cli.ply" || fail "reconstruct_points and envcrust reconstruct wrote different meshes"
echo "install test: passed (installed package found, example built, hemisphere reconstructed as a disc, as envcrust reconstruct does)"
