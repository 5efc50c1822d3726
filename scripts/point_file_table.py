#!/usr/bin/env python3
"""Reconstruct point files of the open built-in surfaces (normals estimated, boundary detected)
and compare with what the samples allow (the accuracy bars): mesh->truth
<= 0.5% of the diagonal, truth->mesh <= max(0.5%, 1.1 x gap), gap = the largest distance from the
true boundary to the nearest input point (JSON analysis.reference_boundary_gap). Distances in % of
the diagonal; "ok" when both bars hold and the topology is the surface's.

usage: scripts/point_file_table.py [--binary build/envcrust] [-n 10000] [--noise 0] [--seed 3]
                                   [--flags "--no-boundary-outer-fit"] [surface ...]
"""
import argparse
import json
import os
import shlex
import subprocess
import tempfile

SURFACES = ["cylinder", "paraboloid", "horn", "trefoil-ribbon", "unknot-ribbon", "moebius",
            "hemisphere", "saddle", "square", "cusp"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", default="build/envcrust")
    ap.add_argument("-n", type=int, default=10000)
    ap.add_argument("--noise", type=float, default=0.0)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--flags", default="", help="extra flags of reconstruct")
    ap.add_argument("surfaces", nargs="*", default=SURFACES)
    a = ap.parse_args()
    listing = subprocess.run([a.binary, "sample", "--list", "--json"], capture_output=True, text=True)
    expected = {s["name"]: s["expected"] for s in json.loads(listing.stdout)} if listing.returncode == 0 else {}
    print(f"{'surface':16} {'rho':>7} {'chi':>4} {'loops':>5} {'m->t %':>7} {'t->m %':>7} {'bar %':>7}  verdict")
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.surfaces:
            points = os.path.join(tmp, f"{name}.xyz")
            subprocess.run([a.binary, "sample", name, "-n", str(a.n), "--seed", str(a.seed), "--noise",
                            str(a.noise), "-q", "-o", points], check=True)
            p = subprocess.run([a.binary, "reconstruct", points, "-r", f"builtin:{name}", "-o",
                                os.path.join(tmp, f"{name}.ply"), "--json", "--quiet"] + shlex.split(a.flags),
                               capture_output=True, text=True)
            if p.returncode != 0:
                print(f"{name:16} FAILED {p.stderr.strip()[-300:]}")
                failures += 1
                continue
            report = json.loads(p.stdout)
            an = report["analysis"]
            m2t = 100 * an["distance"]["mesh_to_reference"]["max_rel_diag"]
            t2m = 100 * an["distance"]["reference_to_mesh"]["max_rel_diag"]
            bar = max(0.5, 110 * an["reference_boundary_gap"]["max_rel_diag"])
            e = expected.get(name, {})
            topology_ok = (an["euler_characteristic"] == e.get("euler_characteristic", an["euler_characteristic"]) and
                           an["boundary_loops"] == e.get("boundary_loops", an["boundary_loops"]))
            problems = [w for w, bad in (("topology", not topology_ok), ("mesh->truth", m2t > 0.5),
                                         ("truth->mesh", t2m > bar)) if bad]
            failures += bool(problems)
            print(f"{name:16} {report['envelope']['rho']:7.4f} {an['euler_characteristic']:>4} {an['boundary_loops']:>5} {m2t:7.3f} {t2m:7.3f} "
                  f"{bar:7.3f}  {'ok' if not problems else 'over: ' + ', '.join(problems)}", flush=True)
    print(f"{failures} of {len(a.surfaces)} outside the bars")


if __name__ == "__main__":
    main()
