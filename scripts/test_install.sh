#!/usr/bin/env bash
# The installed package, as a user takes it: install a built tree into a temporary prefix,
# build examples/cpp against it with find_package(envcrust), and reconstruct 2,000 samples of
# the built-in hemisphere with that program (a disc: chi 1, one boundary loop), byte for byte
# the mesh `envcrust reconstruct` writes from them (the library's input stage is the CLI's);
# with the Python module built, the installed module reconstructs the same faces.
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
# The Python module, when the build has it (ENVCRUST_PYTHON): installed under the prefix, it
# imports from there and reconstructs the same points as the CLI's mesh.
if compgen -G "$build/python/envcrust*.so" >/dev/null; then
  module="$(find "$work/prefix" -name 'envcrust*.so' -path '*-packages/*' | head -1)"
  [ -n "$module" ] || fail "the install has no Python module"
  python=python3  # the interpreter Debian's python3-numpy serves, as cmake/envcrust_python.cmake chooses
  [ -x /usr/bin/python3 ] && python=/usr/bin/python3
  PYTHONPATH="$(dirname "$module")" "$python" - "$work/points.xyz" "$work/cli.ply" "$work/prefix" <<'PY' || fail "the installed Python module"
import sys, numpy as np, envcrust
assert envcrust.__file__.startswith(sys.argv[3]), envcrust.__file__
result = envcrust.reconstruct(envcrust.read_points(sys.argv[1])["points"])
vertices, faces = envcrust.read_mesh(sys.argv[2])
a = result.report["analysis"]
assert (a["euler_characteristic"], a["boundary_loops"]) == (1, 1), a
def triangles(f):  # each with its smallest index first, winding kept: the set, not the order
    return {tuple(np.roll(t, -int(np.argmin(t)))) for t in f}
assert triangles(faces) == triangles(result.faces), "faces differ from envcrust reconstruct's"
print(f"python module: {envcrust.__file__}: {len(result.faces)} faces, chi 1, 1 loop, as envcrust reconstruct")
PY
fi
echo "install test: passed (installed package found, example built, hemisphere reconstructed as a disc, as envcrust reconstruct does)"
