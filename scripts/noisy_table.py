#!/usr/bin/env python3
"""Reconstruct the smooth built-in surfaces from noisy samples and print a table (the bar:
right topology and mesh->truth <= 0.5% of the diagonal). Distances in % of the diagonal; bnd =
worst true boundary loop to its reconstructed loop; seconds are wall clock.

usage: scripts/noisy_table.py [--binary build/envcrust] [-n 10000] [--noise 0.0025] [--seed 3]
                              [--jobs 1] [surface ...]
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import tempfile

SURFACES = ["cylinder", "paraboloid", "horn", "trefoil-ribbon", "unknot-ribbon", "moebius",
            "hemisphere", "saddle", "sphere", "torus"]


def run(binary, name, n, noise, seed, tmp):
    out = os.path.join(tmp, f"{name}-{n}.ply")
    p = subprocess.run([binary, "reconstruct", f"builtin:{name}", "-n", str(n), "--noise", str(noise),
                        "--seed", str(seed), "-o", out, "--json", "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return name, None, p.stderr.strip()[-300:]
    return name, json.loads(p.stdout), ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", default="build/envcrust")
    ap.add_argument("-n", type=int, default=10000)
    ap.add_argument("--noise", type=float, default=0.0025)
    ap.add_argument("--seed", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("surfaces", nargs="*", default=SURFACES)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        futures = [pool.submit(run, a.binary, s, a.n, a.noise, a.seed, tmp) for s in a.surfaces]
        print(f"{'surface':16} {'chi':>4} {'loops':>5} {'orient':>6} {'knots':24} "
              f"{'m->t %':>7} {'t->m %':>7} {'bnd %':>7} {'env s':>6} {'ext s':>6}")
        worst = 0.0
        for f in futures:
            name, d, err = f.result()
            if d is None:
                print(f"{name:16} FAILED {err}")
                continue
            an = d["analysis"]
            dist = an["distance"]
            knots = ",".join((l.get("knot") or {}).get("type", "?") for l in an["loops"])
            m2t = 100 * dist["mesh_to_reference"]["max_rel_diag"]
            t2m = 100 * dist["reference_to_mesh"]["max_rel_diag"]
            bnd = 100 * max((b["hausdorff_rel_diag"] for b in an.get("boundary_matches", [])), default=0.0)
            worst = max(worst, m2t)
            print(f"{name:16} {an['euler_characteristic']:>4} {an['boundary_loops']:>5} "
                  f"{str(an['is_orientable']):>6} {knots:24} {m2t:7.3f} {t2m:7.3f} {bnd:7.3f} "
                  f"{d['seconds']['envelope']:6.1f} {d['seconds']['extraction']:6.1f}", flush=True)
        print(f"worst mesh->truth {worst:.3f}%")


if __name__ == "__main__":
    main()
