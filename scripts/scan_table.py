#!/usr/bin/env python3
"""Re-measure the real-scan rows of docs/real-scans.md (the scan data is not in the repository;
--data or the environment variable ENVCRUST_SHARED_DATA names its folder).

Runs `envcrust reconstruct` on each scan with the row's flags, one after another, and prints
one Markdown row per scan: rho, chi, loops, pieces and their genus, both distances (% of the
reference's diagonal), crossings (found -> relaxed / cut -> left), wall time and peak memory.

    scripts/scan_table.py [--binary build/envcrust] [--data DATA] [NAME ...]

NAME picks rows (foot, foot-width, foot-mesh, bunny, bunny-adaptive, lion, lion-mesh, bun000,
bun045, dragon, face, face-mesh, b9, b9-keep); none = all but face-mesh (5 min, 5.6 GB).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

# name: (input, reference, flags)
ROWS = {
    "foot": ("foot_vhacd/points.xyz", "foot_vhacd/foot_open.off", []),
    "foot-width": ("foot_vhacd/points.xyz", "foot_vhacd/foot_open.off", ["--boundary-min-width", "7"]),
    "foot-mesh": ("foot_vhacd/foot_open.off", "foot_vhacd/foot_open.off", []),
    "bunny": ("stanford_bunny_zipper/points.xyz", "stanford_bunny_zipper/bun_zipper.ply", []),
    "bunny-adaptive": ("stanford_bunny_zipper/points.xyz", "stanford_bunny_zipper/bun_zipper.ply", ["--rho-adaptive"]),
    "lion": ("cgal_lion_head/points.xyz", "cgal_lion_head/lion-head.off", []),
    "lion-mesh": ("cgal_lion_head/lion-head.off", "cgal_lion_head/lion-head.off", []),
    "bun000": ("stanford_bunny_range_scans/bun000_points.xyz", "stanford_bunny_range_scans/bun000_points.xyz", []),
    "bun045": ("stanford_bunny_range_scans/bun045_points.xyz", "stanford_bunny_range_scans/bun045_points.xyz", []),
    "dragon": ("stanford_dragon_range_scan/dragonStandRight_0_points.xyz",
               "stanford_dragon_range_scan/dragonStandRight_0_points.xyz", []),
    "face": ("face_yh_scan_vhacd/points.xyz", "face_yh_scan_vhacd/face-YH.off", []),
    "face-mesh": ("face_yh_scan_vhacd/face-YH.off", "face_yh_scan_vhacd/face-YH.off", []),
    "b9": ("cgal_b9_aerial_lidar/points.xyz", "cgal_b9_aerial_lidar/points.xyz", []),
    "b9-keep": ("cgal_b9_aerial_lidar/points.xyz", "cgal_b9_aerial_lidar/points.xyz", ["--keep-outliers"]),
}


def row(binary, data, name):
    source, reference, flags = ROWS[name]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.ply")
        command = ["/usr/bin/time", "-f", "%M", binary, "reconstruct", os.path.join(data, source), "-o", out,
                   "--reference", os.path.join(data, reference), "--json", "--quiet"] + flags
        start = time.monotonic()
        run = subprocess.run(command, capture_output=True, text=True)
        seconds = time.monotonic() - start
    if run.returncode != 0:
        return f"| {name} | {' '.join(flags) or 'defaults'} | failed: {run.stderr.strip()} |"
    peak_gb = int(run.stderr.strip().splitlines()[-1]) / 1024 / 1024
    j = json.loads(run.stdout)
    a, e, s = j["analysis"], j["envelope"], j["sheet"]
    rho = f"{e['rho_min']:.4g}" if abs(e["rho_min"] - e["rho"]) < 1e-12 else f"{e['rho_min']:.4g}–{e['rho']:.4g}"
    genus = [c["genus"] for c in a["component_list"]]
    d = a["distance"]
    crossings = (f"{s['self_intersections_found']} → {s['self_intersections_smoothed']} / "
                 f"{s['self_intersections_cut']} → {a['self_intersections']['face_pairs']}")
    return (f"| {name} | {' '.join(flags) or 'defaults'} | {rho} | {a['euler_characteristic']} | {len(a['loops'])} | "
            f"{'yes' if a['is_orientable'] else 'no'} ({len(genus)} pieces, genus {genus}) | "
            f"{100 * d['mesh_to_reference']['max_rel_diag']:.2f}% | {100 * d['reference_to_mesh']['max_rel_diag']:.2f}% | "
            f"{crossings} | {seconds:.0f} s, {peak_gb:.2f} GB |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/envcrust")
    parser.add_argument("--data", default=os.environ.get("ENVCRUST_SHARED_DATA"),
                        help="the folder of the scans (env ENVCRUST_SHARED_DATA)")
    parser.add_argument("names", nargs="*")
    args = parser.parse_args()
    names = args.names or [n for n in ROWS if n != "face-mesh"]
    unknown = [n for n in names if n not in ROWS]
    if unknown:
        sys.exit(f"scan_table.py: unknown row {', '.join(unknown)} (rows: {', '.join(ROWS)})")
    if not args.data or not os.path.isdir(args.data):
        sys.exit(f"scan_table.py: {args.data or 'no --data'}: no such folder (the scans are not in the repository; "
                 "give --data DIR or set ENVCRUST_SHARED_DATA)")
    print("| scan | flags | ρ | χ | loops | orientable | mesh→truth | truth→mesh | crossings | time, peak |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name in names:
        print(row(args.binary, args.data, name), flush=True)


if __name__ == "__main__":
    main()
