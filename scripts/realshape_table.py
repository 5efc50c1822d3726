#!/usr/bin/env python3
"""The real-shapes development set (issue 45): envcrust and CGAL's advancing front, side by side.

For every input (points sampled from a real mesh, its vertices, or a scan), runs
`envcrust reconstruct POINTS -o out.ply --json` with the defaults, as a new user would, and
`afsr_peer POINTS -o out.ply` (bench/afsr_peer.cpp: CGAL's advancing-front reconstruction)
on the same points, then measures both outputs against the truth mesh with
`envcrust analyze OUT --reference TRUTH --json --no-knots`. Prints one Markdown row per input
and writes every measurement to --out (rewritten after each row, so a long run can be
watched, stopped and resumed with --resume).

    scripts/realshape_table.py [--data DIR] [--scans DIR] [--shapes a,b,...] [--variants v,...]
                               [--timeout 600] [--jobs 1] [--out results.json] [--resume]

Inputs, named SHAPE/VARIANT:
  SHAPE: a mesh of CGAL's example data (data/meshes/SHAPE.off; the list is OPEN + CLOSED
         below), or scan:NAME, a scan in the --scans folder with its own mesh as truth (SCANS below),
         or builtin:NAME, a built-in surface with its fine tessellation as truth (BUILTINS; not
         in the default set: --shapes builtins; no verts variant).
         --shapes also takes the groups open, closed, scans, builtins.
  VARIANT (mesh shapes only; scans are their own points, variant `points`):
    s30k       30,000 points, uniform by area (seeded by the shape's name: same points each run);
    verts      the mesh's vertices (those on a face);
    ramp20     30,000 points whose density grows 20-fold along the mesh's longest box axis
               (rejection from the uniform sampler: kept with probability 20^(t-1), t in [0, 1]);
    noise0.5, noise1
               the s30k points moved by Gaussian noise of sigma 0.5% / 1% of the mesh's
               box diagonal (each coordinate).
  s30k and verts run on every shape, ramp20 and noise on VARIANT_SHAPES (--variants picks).

The data: CGAL's example data is not in the repository and must not be committed. Found
through --data or the environment variable ENVCRUST_CGAL_DATA (the folder holding `meshes/`);
when absent the script prints the commands that unpack it from Debian's libcgal-demo.
The scans: --scans or the environment variable ENVCRUST_SHARED_DATA (no default; needed only
for scan: inputs).

Topology "right": the output's Euler characteristic, boundary loop count, orientability and
number of pieces all equal the truth mesh's (as `envcrust analyze` reads both), or, where the
truth has a hole no larger than the largest gap the points leave beside it (its radius,
2 area / length, no larger than R, the largest distance from the truth's surface within one
hole diameter of the boundary to its nearest input point), the truth's with each such hole
filled: the points cannot tell it from a gap. The truth cell names those holes ("resolved:
..."). Distances are
the largest distance output->truth and truth->output, in % of the truth's box diagonal. Time
is the wall clock of the whole command (envcrust's includes reading, normals, its own analysis
against the input points, and writing; afsr_peer's reading and writing); peak is the largest
resident size of the process (/usr/bin/time for envcrust, afsr_peer's own VmHWM). The raw
sheet's defects are envcrust's report counts before its repairs: orientation seams, balls
where the sheet is not a disc (the handle cut's balls), and face pairs that cross (found
before relaxation and cuts); "(adaptive)" or "(power crust)" after them says which of
envcrust's runs was kept (the counts are those of the sheet it reports).
"""
import argparse
import bisect
import json
import math
import os
import random
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time
import zlib
from concurrent.futures import ThreadPoolExecutor

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

OPEN = ["head", "holes", "mushroom", "horizons", "lion", "pig", "nefertiti", "cylinder_locally_refined",
        "patch-01", "mask_cone"]
CLOSED = ["armadillo", "bunny00", "camel", "elephant", "femur", "knot1", "fandisk", "rotor_small", "turbine",
          "man", "triceratops", "bear"]
# scan name: (points, truth mesh), under --scans
SCANS = {
    "foot": ("foot_vhacd/points.xyz", "foot_vhacd/foot_open.off"),
    "lion-head": ("cgal_lion_head/points.xyz", "cgal_lion_head/lion-head.off"),
    "face": ("face_yh_scan_vhacd/points.xyz", "face_yh_scan_vhacd/face-YH.off"),
    "bunny": ("stanford_bunny_zipper/points.xyz", "stanford_bunny_zipper/bun_zipper.ply"),
}
MESH_VARIANTS = ["s30k", "verts", "ramp20", "noise0.5", "noise1"]
VARIANT_SHAPES = ["head", "mushroom", "pig", "bunny00", "knot1", "fandisk"]
# built-in surfaces (not in the default set: --shapes builtins), truth = `envcrust sample NAME --mesh`
BUILTINS = ["trefoil-ribbon", "moebius", "hemisphere", "torus", "cylinder", "saddle"]
SAMPLES = 30000
RAMP = 20.0

GET_DATA = """CGAL's example data was not found. It comes from Debian's libcgal-demo (never commit it):
    apt-get download libcgal-demo
    dpkg-deb -x libcgal-demo_*_all.deb cgal-demo
    mkdir -p cgal-demo/data && tar -xzf cgal-demo/usr/share/doc/libcgal-dev/data.tar.gz -C cgal-demo/data
    export ENVCRUST_CGAL_DATA=$PWD/cgal-demo/data/data     # the folder that holds meshes/
then run this script again (or pass --data cgal-demo/data/data)."""


# ---------------------------------------------------------------------------------------------
# Meshes and sampling (plain standard library: no numpy here)

def read_off(path):
    """Vertices and triangles (polygons fanned) of an OFF file; comments and colours ignored."""
    with open(path) as f:
        tokens = []
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                tokens.append(line)
    head = tokens[0]
    if not head[0].upper().endswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    rest = head[1:] if len(head) > 1 else None
    lines = tokens[1:]
    if rest is None:
        rest, lines = lines[0], lines[1:]
    nv, nf = int(rest[0]), int(rest[1])
    vertices = [tuple(float(x) for x in lines[i][:3]) for i in range(nv)]
    triangles = []
    for line in lines[nv:nv + nf]:
        n = int(line[0])
        ids = [int(x) for x in line[1:1 + n]]
        for k in range(1, n - 1):
            triangles.append((ids[0], ids[k], ids[k + 1]))
    return vertices, triangles


def area(a, b, c):
    u = (b[0] - a[0], b[1] - a[1], b[2] - a[2])
    v = (c[0] - a[0], c[1] - a[1], c[2] - a[2])
    x, y, z = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]
    return 0.5 * math.sqrt(x * x + y * y + z * z)


def box(points):
    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    return lo, hi


def sample_mesh(vertices, triangles, count, seed, ramp=None, noise=0.0):
    """count points uniform by area (triangle by area, then uniform in it); with ramp = R the
    density grows R-fold along the box's longest axis (rejection); noise = Gaussian sigma as a
    fraction of the box diagonal."""
    rng = random.Random(seed)
    cumulative, total = [], 0.0
    for t in triangles:
        total += area(vertices[t[0]], vertices[t[1]], vertices[t[2]])
        cumulative.append(total)
    lo, hi = box([vertices[i] for t in triangles for i in t])
    axis = max(range(3), key=lambda i: hi[i] - lo[i])
    diagonal = math.dist(lo, hi)
    points = []
    while len(points) < count:
        t = triangles[min(bisect.bisect_left(cumulative, rng.random() * total), len(triangles) - 1)]
        a, b, c = vertices[t[0]], vertices[t[1]], vertices[t[2]]
        r1, r2 = math.sqrt(rng.random()), rng.random()
        p = tuple((1 - r1) * a[i] + r1 * (1 - r2) * b[i] + r1 * r2 * c[i] for i in range(3))
        if ramp is not None:
            s = (p[axis] - lo[axis]) / (hi[axis] - lo[axis])
            if rng.random() >= ramp ** (s - 1):
                continue
        points.append(p)
    if noise > 0:
        sigma = noise * diagonal
        points = [tuple(x + rng.gauss(0, sigma) for x in p) for p in points]
    return points


def write_xyz(path, points):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        for p in points:
            f.write(f"{p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
    os.replace(tmp, path)


def without_repeated_faces(truth, args):
    """truth, or a copy of it in --work without its repeated triangles (the face scan's mesh
    repeats 18, which make it read as non-manifold)."""
    if not truth.endswith(".off"):
        return truth
    clean = os.path.join(args.work, "truth", os.path.basename(truth)[:-4] + ".unique.off")
    if os.path.exists(clean):
        return clean
    vertices, triangles = read_off(truth)
    seen, unique = set(), []
    for t in triangles:
        if tuple(sorted(t)) not in seen:
            seen.add(tuple(sorted(t)))
            unique.append(t)
    if len(unique) == len(triangles):
        return truth
    os.makedirs(os.path.dirname(clean), exist_ok=True)
    with open(clean + ".tmp", "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(unique)} 0\n")
        f.writelines(f"{v[0]!r} {v[1]!r} {v[2]!r}\n" for v in vertices)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in unique)
    os.replace(clean + ".tmp", clean)
    return clean


def make_input(name, args):
    """(points file, truth mesh) of input SHAPE/VARIANT, writing the points file if need be."""
    shape, variant = name.split("/")
    if shape.startswith("scan:"):
        points, truth = SCANS[shape[5:]]
        return os.path.join(args.scans, points), without_repeated_faces(os.path.join(args.scans, truth), args)
    if shape.startswith("builtin:"):
        truth = os.path.join(args.work, "truth", shape[8:] + ".off")
        if not os.path.exists(truth):
            os.makedirs(os.path.dirname(truth), exist_ok=True)
            subprocess.run([args.envcrust, "sample", shape[8:], "--mesh", "-o", truth, "--quiet"], check=True)
    else:
        truth = os.path.join(args.data, "meshes", shape + ".off")
    path = os.path.join(args.work, "inputs", f"{shape.replace(':', '_')}.{variant}.xyz")
    if os.path.exists(path):
        return path, truth
    os.makedirs(os.path.dirname(path), exist_ok=True)
    vertices, triangles = read_off(truth)
    seed = zlib.crc32(shape.encode())  # fixed per shape; the variants share the uniform draw
    if variant == "verts":
        used = sorted({i for t in triangles for i in t})
        points = [vertices[i] for i in used]
    elif variant == "s30k":
        points = sample_mesh(vertices, triangles, SAMPLES, seed)
    elif variant == "ramp20":
        points = sample_mesh(vertices, triangles, SAMPLES, seed, ramp=RAMP)
    elif variant.startswith("noise"):
        points = sample_mesh(vertices, triangles, SAMPLES, seed, noise=float(variant[5:]) / 100)
    else:
        raise ValueError(f"unknown variant {variant}")
    write_xyz(path, points)
    return path, truth


# ---------------------------------------------------------------------------------------------
# Runs

def run(command, timeout):
    """(return code or 'timeout', stdout, stderr, seconds, peak MB) of command under /usr/bin/time."""
    start = time.monotonic()
    process = subprocess.Popen(["/usr/bin/time", "-f", "PEAK_KB %M"] + command, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        return "timeout", out, err, time.monotonic() - start, None
    seconds = time.monotonic() - start
    peak, lines = None, []
    for line in err.splitlines():
        if line.startswith("PEAK_KB "):
            peak = int(line.split()[1]) / 1024
        elif not line.startswith("Command exited with non-zero status"):
            lines.append(line)
    return process.returncode, out, "\n".join(lines), seconds, peak


def topology(analysis):
    return {"chi": analysis["euler_characteristic"], "loops": analysis["boundary_loops"],
            "orientable": analysis["is_orientable"], "pieces": analysis["components"]}


def analyze(binary, mesh, truth, timeout):
    command = [binary, "analyze", mesh, "--json", "--quiet", "--no-knots"]
    if truth:
        command += ["--reference", truth]
    code, out, err, seconds, _ = run(command, timeout)
    if code != 0:
        return {"error": f"analyze {code}: {err.strip()[-300:]}"}
    a = json.loads(out)
    result = {"topology": topology(a), "vertices": a["vertices"], "faces": a["faces"],
              "is_manifold": a["is_manifold"], "analyze_seconds": round(seconds, 2),
              "genus": [c["genus"] for c in a["component_list"]]}
    if "self_intersections" in a:
        result["crossings"] = a["self_intersections"]["face_pairs"]
    if "distance" in a:
        d = a["distance"]
        result["mesh_to_truth_pct"] = 100 * d["mesh_to_reference"]["max_rel_diag"]
        result["truth_to_mesh_pct"] = 100 * d["reference_to_mesh"]["max_rel_diag"]
        result["mesh_to_truth_mean_pct"] = 100 * d["mesh_to_reference"]["mean_rel_diag"]
        result["truth_to_mesh_mean_pct"] = 100 * d["reference_to_mesh"]["mean_rel_diag"]
    return result


def truth_topology(binary, truth, args):
    cache = os.path.join(args.work, "truth", os.path.basename(truth) + ".json")
    if os.path.exists(cache):
        with open(cache) as f:
            return json.load(f)
    code, out, err, _, _ = run([binary, "analyze", truth, "--json", "--quiet", "--no-knots",
                                "--no-self-intersections"], args.timeout)
    if code != 0:
        return {"error": f"analyze {code}: {err.strip()[-300:]}"}
    a = json.loads(out)
    result = {"topology": topology(a), "vertices": a["vertices"], "is_manifold": a["is_manifold"],
              "genus": [c["genus"] for c in a["component_list"]]}
    os.makedirs(os.path.dirname(cache), exist_ok=True)
    with open(cache, "w") as f:
        json.dump(result, f)
    return result


def boundary_loops(triangles):
    """The truth's boundary loops as lists of boundary edges (vertex pairs in their face's
    order), one list per connected set of boundary edges."""
    count, directed = {}, {}
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = (a, b) if a < b else (b, a)
            count[key] = count.get(key, 0) + 1
            directed[key] = (a, b)
    edges = [directed[e] for e, n in count.items() if n == 1]
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for a, b in edges:
        parent[find(a)] = find(b)
    loops = {}
    for e in edges:
        loops.setdefault(find(e[0]), []).append(e)
    return list(loops.values())


def loop_length(vertices, loop):
    return sum(math.dist(vertices[a], vertices[b]) for a, b in loop)


def hole_radius(vertices, loop, length):
    """2 area / length: a round hole's radius and a triangular one's inscribed circle; for a
    slot, its width, twice its inscribed circle (so a slot counts as resolved sooner, the strict
    side for the tool measured). The area is the size of the loop's vector area (the hole's area
    where it is near planar)."""
    ax = ay = az = 0.0
    for a, b in loop:
        p, q = vertices[a], vertices[b]
        ax += p[1] * q[2] - p[2] * q[1]
        ay += p[2] * q[0] - p[0] * q[2]
        az += p[0] * q[1] - p[1] * q[0]
    return math.sqrt(ax * ax + ay * ay + az * az) / length if length > 0 else 0.0


def local_gap(binary, vertices, triangles, loop, length, points, work, name, timeout):
    """The largest distance from the truth's surface within one hole diameter (length / pi) of a
    boundary loop to its nearest input point: the largest gap the points leave around the hole.
    Measured by `analyze` on that piece of the truth with the points as reference."""
    reach = length / math.pi
    rim = sorted({v for e in loop for v in e})
    lo = [min(vertices[v][i] for v in rim) - reach for i in range(3)]
    hi = [max(vertices[v][i] for v in rim) + reach for i in range(3)]

    def near(v):
        p = vertices[v]
        return all(lo[i] <= p[i] <= hi[i] for i in range(3)) and \
            min(math.dist(p, vertices[r]) for r in rim) <= reach
    near_cache = {}
    piece = [t for t in triangles
             if all(near_cache.setdefault(v, near(v)) for v in t)]
    used = sorted({v for t in piece for v in t})
    index = {v: i for i, v in enumerate(used)}
    path = os.path.join(work, "truth", f"{name}.hole.off")
    with open(path, "w") as f:
        f.write(f"OFF\n{len(used)} {len(piece)} 0\n")
        f.writelines(f"{vertices[v][0]!r} {vertices[v][1]!r} {vertices[v][2]!r}\n" for v in used)
        f.writelines(f"3 {index[t[0]]} {index[t[1]]} {index[t[2]]}\n" for t in piece)
    code, out, err, _, _ = run([binary, "analyze", path, "--reference", points, "--json", "--quiet",
                                "--no-knots", "--no-self-intersections"], timeout)
    os.remove(path)
    if code != 0:
        raise ValueError(f"analyze of the piece round a hole: {err.strip()[-200:]}")
    return json.loads(out)["distance"]["mesh_to_reference"]["max"]


def sampling_resolution(binary, truth, points, key, truth_topo, args):
    """Which of the truth's holes the points resolve. Around each hole (the truth's surface
    within one hole diameter, length / pi, of its boundary) the largest gap the points leave is
    R, the largest distance from there to the nearest input point. A hole whose size (radius
    2 area / length, hole_radius) is no larger than R is no larger than a gap the points leave
    beside it: no method can tell it from one. The topology the points resolve is the truth's
    with each such hole filled by a disc (chi + 1, one loop fewer). OFF truths only."""
    cache = os.path.join(args.work, "truth", key + ".resolution.json")
    if os.path.exists(cache):
        with open(cache) as f:
            return json.load(f)
    if "topology" not in truth_topo or truth_topo["topology"]["loops"] == 0 or not truth.endswith(".off"):
        return {}
    vertices, triangles = read_off(truth)
    holes = []
    for i, loop in enumerate(boundary_loops(triangles)):
        length = loop_length(vertices, loop)
        try:
            gap = local_gap(binary, vertices, triangles, loop, length, points, args.work, f"{key}.{i}",
                            args.timeout)
        except ValueError as error:
            return {"error": str(error)}
        radius = hole_radius(vertices, loop, length)
        holes.append({"length": length, "radius": radius, "largest_gap_around": gap,
                      "resolved": radius > gap})
    unresolved = sum(1 for h in holes if not h["resolved"])
    topology = dict(truth_topo["topology"])
    topology["chi"] += unresolved
    topology["loops"] -= unresolved
    result = {"holes": holes, "unresolved_holes": unresolved, "topology": topology}
    os.makedirs(os.path.dirname(cache), exist_ok=True)
    with open(cache, "w") as f:
        json.dump(result, f)
    return result


def count_points(path):
    with open(path) as f:
        return sum(1 for line in f if line.strip() and not line.lstrip().startswith("#"))


def points_diagonal(path):
    """The box diagonal of a point file's x y z columns."""
    with open(path) as f:
        points = [tuple(map(float, line.split()[:3])) for line in f
                  if line.strip() and not line.lstrip().startswith("#")]
    lo, hi = box(points)
    return math.dist(lo, hi)


def run_envcrust(args, points, out_dir, truth_topo):
    out = os.path.join(out_dir, "envcrust.ply")
    extra = args.envcrust_args.split()
    if args.rho_rel_diag:
        extra += ["--rho", repr(args.rho_rel_diag * points_diagonal(points))]
    code, stdout, err, seconds, peak = run([args.envcrust, "reconstruct", points, "-o", out, "--json",
                                            "--quiet"] + extra, args.timeout)
    result = {"seconds": round(seconds, 2), "peak_mb": peak and round(peak)}
    if code == "timeout":
        result["error"] = f"timeout after {args.timeout} s"
        return result
    if code == 4 and os.path.exists(out) and stdout.strip():
        # exit 4: the mesh is written, but fails envcrust's own checks (it says which): measured
        # as it is, since a user gets it, and the message kept.
        result["own_checks_failed"] = err.strip().splitlines()[-1][-300:] if err.strip() else "exit 4"
    elif code != 0:
        result["error"] = f"exit {code}: {err.strip()[-300:]}"
        return result
    j = json.loads(stdout)
    s, e = j.get("sheet", {}), j.get("envelope") or {}
    result["stage_seconds"] = j.get("seconds")
    result["rho"] = e.get("rho")
    result["rho_min"] = e.get("rho_min")
    result["envelope_samples"] = e.get("samples")
    result["raw_sheet"] = {k: s.get(k) for k in ("orientation_seams", "handle_balls", "self_intersections_found",
                                                  "self_intersections_left", "cut_holes_filled",
                                                  "cut_notches_closed")}
    local = j.get("local_rho_first")
    if local:
        result["local_rho_first"] = {k: local.get(k) for k in ("kept", "seconds", "envelope_samples",
                                                              "orientation_seams", "handle_balls")}
    first = j.get("power_crust_first")
    if first:
        result["power_crust_first"] = {k: first.get(k) for k in ("kept", "seconds")}
    result["kept"] = ("power crust first" if first and first.get("kept") else
                      "local" if local and local.get("kept") else
                      "power crust" if j.get("power_crust_fallback", {}).get("kept") == "power_crust" else
                      "adaptive" if j.get("adaptive_retry", {}).get("kept") == "adaptive" else "uniform")
    # What the output is: the input points meshed along the sheet, the sheet or Power Crust
    # simplified to the samples' resolution, the result remeshed (--remesh in
    # --envcrust-args), or the sheet or Power Crust as extracted.
    meshing, remesh, simplify = j.get("sample_meshing"), j.get("remesh", {}), j.get("simplify", {})
    result["output"] = ("samples" if meshing and meshing.get("is_kept") else
                        "simplified" if simplify.get("is_simplified") else
                        "remeshed" if remesh.get("is_remeshed") else "extracted")
    result["remesh_seconds"] = remesh.get("seconds")
    result["simplify_seconds"] = simplify.get("seconds")
    result.update(analyze(args.envcrust, out, args.truth_of[points], args.timeout))
    if not args.keep_meshes:
        os.remove(out) if os.path.exists(out) else None
    return result


def run_afsr(args, points, out_dir, truth_topo):
    out = os.path.join(out_dir, "afsr.ply")
    code, stdout, err, seconds, peak = run([args.afsr, points, "-o", out], args.timeout)
    result = {"seconds": round(seconds, 2), "peak_mb": peak and round(peak)}
    if code == "timeout":
        result["error"] = f"timeout after {args.timeout} s"
        return result
    if code != 0:
        result["error"] = f"exit {code}: {err.strip()[-300:]}"
        return result
    j = json.loads(stdout)
    result["seconds_reconstruction"] = j["seconds_reconstruction"]
    # afsr_peer reads its peak (VmHWM) itself and resets it as it does (bench/peak_memory.h),
    # which leaves /usr/bin/time the size after the reset: take the program's own figure.
    result["peak_mb"] = round(j["peak_mb"])
    if j["faces"] == 0:
        result["error"] = "no faces"
        return result
    result.update(analyze(args.envcrust, out, args.truth_of[points], args.timeout))
    if not args.keep_meshes:
        os.remove(out) if os.path.exists(out) else None
    return result


def measure(name, args):
    try:
        points, truth = make_input(name, args)
    except (OSError, ValueError) as error:
        return {"input": name, "error": str(error)}
    args.truth_of[points] = truth
    row = {"input": name, "points_file": points, "truth": truth, "points": count_points(points),
           "truth_analysis": truth_topology(args.envcrust, truth, args)}
    key = name.replace("/", ".").replace(":", "_")
    row["resolution"] = sampling_resolution(args.envcrust, truth, points, key, row["truth_analysis"], args)
    # Right: the topology the samples resolve (the truth's, unless a hole is below the sampling).
    expected = row["resolution"].get("topology") or row["truth_analysis"].get("topology")
    out_dir = os.path.join(args.work, "out", key)
    os.makedirs(out_dir, exist_ok=True)
    for tool, runner in (("afsr", run_afsr), ("envcrust", run_envcrust)):
        row[tool] = runner(args, points, out_dir, row["truth_analysis"])
        if "topology" in row[tool] and expected:
            row[tool]["topology_right"] = row[tool]["topology"] == expected
    return row


# ---------------------------------------------------------------------------------------------
# The table

def topo_text(t):
    return f"χ {t['chi']}, {t['loops']} loops, {'or.' if t['orientable'] else 'non-or.'}, {t['pieces']} pc"


def pct(x):
    return "–" if x is None else f"{x:.2f}%" if x < 10 else f"{x:.0f}%"


def tool_cells(r, raw=False):
    if r is None:
        return ["not run"] + [""] * (7 if raw else 6)
    if "error" in r:
        message = re.sub(r"envcrust: error: [^ ]*: ", "", r["error"])
        cells = [f"**{message[:110]}**", "✗", "", "", f"{r['seconds']:.1f}",
                 "" if r.get("peak_mb") is None else f"{r['peak_mb']}", ""]
        return cells + ([""] if raw else [])
    cells = [topo_text(r["topology"]), "✓" if r.get("topology_right") else "✗",
             pct(r.get("mesh_to_truth_pct")), pct(r.get("truth_to_mesh_pct")), f"{r['seconds']:.1f}",
             f"{r['peak_mb']}", f"{r['vertices']:,}"]
    if raw:
        s = r.get("raw_sheet") or {}
        defects = f"{s.get('orientation_seams')} / {s.get('handle_balls')} / {s.get('self_intersections_found')}"
        if r.get("kept") != "uniform":
            defects += f" ({r.get('kept')})"
        if r.get("output") and r.get("output") != "samples":
            defects += f", output {r['output']}"
        if r.get("own_checks_failed"):
            checks = r["own_checks_failed"].split("fails its checks: ")[-1].split("; ")
            defects += " [fails own checks: " + checks[0] + (f"; +{len(checks) - 1} more" if len(checks) > 1 else "") + "]"
        cells.append(defects)
    return cells


HEADER = ("| input | points | truth | envcrust | ok | m→t | t→m | s | MB | verts | raw seams / balls / crossings "
          "| AFSR | ok | m→t | t→m | s | MB | verts |")


def row_text(row):
    truth = row.get("truth_analysis", {})
    truth_cell = topo_text(truth["topology"]) if "topology" in truth else truth.get("error", row.get("error", ""))
    holes = row.get("resolution", {}).get("unresolved_holes")
    if holes:
        truth_cell += (f"; resolved: {topo_text(row['resolution']['topology'])} ({holes} hole"
                       f"{'s' if holes > 1 else ''} below the sampling)")
    cells = [row["input"], f"{row.get('points', 0):,}", truth_cell] + tool_cells(row.get("envcrust"), raw=True) + \
        tool_cells(row.get("afsr"))
    return "| " + " | ".join(str(c) for c in cells) + " |"


def summary(rows):
    lines = []
    for tool in ("envcrust", "afsr"):
        done = [r for r in rows if r.get(tool)]
        right = sum(1 for r in done if r[tool].get("topology_right"))
        failed = sum(1 for r in done if "error" in r[tool])
        lines.append(f"- {tool}: topology right on {right} of {len(done)} inputs ({failed} failed or timed out)")
    ratios = [r["envcrust"]["seconds"] / r["afsr"]["seconds"] for r in rows
              if r.get("envcrust") and r.get("afsr") and "error" not in r["envcrust"] and "error" not in r["afsr"]
              and r["afsr"]["seconds"] > 0]
    if ratios:
        lines.append(f"- time envcrust / AFSR (wall clock, both finished): median {statistics.median(ratios):.0f}x "
                     f"(range {min(ratios):.0f}–{max(ratios):.0f}x, {len(ratios)} inputs)")
    for tool in ("envcrust", "afsr"):
        v = [r[tool]["vertices"] / r["points"] for r in rows
             if r.get(tool) and "vertices" in r[tool] and r.get("points")]
        if v:
            lines.append(f"- {tool} output vertices / input points: median {statistics.median(v):.2f} "
                         f"(range {min(v):.2f}–{max(v):.2f})")
    return lines


def group_of(name):
    variant = name.split("/")[1]
    return {"s30k": "30k samples", "points": "scans", "verts": "vertices", "ramp20": "density ramp"}.get(
        variant, "noise")


def summaries(rows):
    """The summary of all rows, then of each group (30k samples, scans, vertices, ramp, noise)."""
    lines = ["All inputs:"] + summary(rows)
    groups = sorted({group_of(r["input"]) for r in rows})
    if len(groups) > 1:
        for g in ("30k samples", "scans", "vertices", "density ramp", "noise"):
            if g in groups:
                lines += ["", f"{g}:"] + summary([r for r in rows if group_of(r["input"]) == g])
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", default=os.environ.get("ENVCRUST_CGAL_DATA"),
                        help="CGAL's example data, the folder holding meshes/ (env ENVCRUST_CGAL_DATA)")
    parser.add_argument("--scans", default=os.environ.get("ENVCRUST_SHARED_DATA"),
                        help="the folder of the scans (env ENVCRUST_SHARED_DATA)")
    parser.add_argument("--envcrust", default=os.path.join(REPO, "build", "envcrust"))
    parser.add_argument("--envcrust-args", default="",
                        help="more options for every envcrust run, e.g. '--extract samples' (default: none)")
    parser.add_argument("--rho-rel-diag", type=float,
                        help="also pass --rho of this fraction of each input's box diagonal (with --envcrust-args "
                             "'--rho-adaptive ...': the ceiling of a local rho field)")
    parser.add_argument("--afsr", default=os.path.join(REPO, "build", "bench", "afsr_peer"))
    parser.add_argument("--shapes", help="comma-separated shapes (mesh names, scan:NAME, or open/closed/scans); "
                                         "default all")
    parser.add_argument("--variants", help=f"comma-separated variants of {MESH_VARIANTS}; default s30k,verts "
                                           f"on every shape and the others on {','.join(VARIANT_SHAPES)}")
    parser.add_argument("--inputs", help="comma-separated SHAPE/VARIANT names, in this order (overrides the two above)")
    parser.add_argument("--timeout", type=float, default=600, help="seconds per run (a timeout is a row)")
    parser.add_argument("--jobs", type=int, default=1, help="inputs measured at once (1: timings undisturbed)")
    parser.add_argument("--out", default="results.json", help="every measurement, rewritten after each row")
    parser.add_argument("--work", default=os.path.join(REPO, "build", "realshapes"),
                        help="sampled inputs, cached truth topology, outputs")
    parser.add_argument("--resume", action="store_true", help="keep the rows already in --out, run the rest")
    parser.add_argument("--keep-meshes", action="store_true", help="keep the output meshes in --work/out")
    parser.add_argument("--list", action="store_true", help="list the inputs and stop")
    parser.add_argument("--prepare", action="store_true", help="write the sampled inputs and stop")
    parser.add_argument("--table", action="store_true", help="print the table of the rows in --out, run nothing")
    parser.add_argument("--redo", help="comma-separated inputs to measure again with --resume")
    args = parser.parse_args()
    args.truth_of = {}

    if args.inputs:
        names = args.inputs.split(",")
    else:
        shapes = []
        for s in (args.shapes.split(",") if args.shapes else ["open", "closed", "scans"]):
            shapes += (OPEN if s == "open" else CLOSED if s == "closed" else
                       [f"scan:{n}" for n in SCANS] if s == "scans" else
                       [f"builtin:{n}" for n in BUILTINS] if s == "builtins" else [s])
        variants = args.variants.split(",") if args.variants else None
        names = []
        for v in MESH_VARIANTS:  # the whole set of one variant before the next
            for s in shapes:
                if s.startswith("scan:"):
                    continue
                if s.startswith("builtin:") and v == "verts":
                    continue
                if variants is None and (v in ("s30k", "verts") or s in VARIANT_SHAPES) or variants and v in variants:
                    names.append(f"{s}/{v}")
            if v == "s30k":
                names += [f"{s}/points" for s in shapes if s.startswith("scan:")]
    if any(not n.startswith(("scan:", "builtin:")) for n in names) and \
            (not args.data or not os.path.isdir(os.path.join(args.data, "meshes"))):
        sys.exit(f"realshape_table.py: {args.data or 'no --data'}: no meshes/ folder\n{GET_DATA}")
    for name in names:
        shape, _, variant = name.partition("/")
        known = (shape[5:] in SCANS and variant == "points") if shape.startswith("scan:") else \
            (shape[8:] in BUILTINS and variant in MESH_VARIANTS and variant != "verts") \
            if shape.startswith("builtin:") else \
            variant in MESH_VARIANTS and os.path.exists(os.path.join(args.data, "meshes", shape + ".off"))
        if not known:
            sys.exit(f"realshape_table.py: unknown input {name} (shapes: {', '.join(OPEN + CLOSED)}, "
                     f"scan:{', scan:'.join(SCANS)}; variants: {', '.join(MESH_VARIANTS)}, points for scans)")
    if any(n.startswith("scan:") for n in names) and (not args.scans or not os.path.isdir(args.scans)):
        sys.exit(f"realshape_table.py: {args.scans or 'no --scans'}: no such folder (the scans are not in the "
                 "repository; give --scans DIR or set ENVCRUST_SHARED_DATA)")
    if args.list or args.prepare:
        for name in names:
            print(name + ("\t" + "\t".join(make_input(name, args)) if args.prepare else ""))
        return
    for binary in () if args.table else (args.envcrust, args.afsr):
        if not os.access(binary, os.X_OK):
            sys.exit(f"realshape_table.py: {binary}: not built (cmake --build build --target envcrust afsr_peer)")

    rows = {}
    if (args.resume or args.table) and os.path.exists(args.out):
        with open(args.out) as f:
            rows = {r["input"]: r for r in json.load(f)["rows"]}
        for name in (args.redo.split(",") if args.redo else []):
            rows.pop(name, None)
    if args.table:
        print(HEADER)
        print("|" + "---|" * (HEADER.count("|") - 1))
        for n in names:
            if n in rows:
                print(row_text(rows[n]))
        print()
        print("\n".join(summaries([rows[n] for n in names if n in rows])))
        return
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    commit = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()

    def save():
        # the rows of this run's inputs first, then those --resume found for other inputs
        done = [rows[n] for n in names if n in rows] + [r for n, r in rows.items() if n not in names]
        tmp = args.out + ".tmp"
        with open(tmp, "w") as f:
            json.dump({"started": started, "commit": commit, "command": " ".join(sys.argv), "rows": done,
                       "summary": summary(done)}, f, indent=1)
        os.replace(tmp, args.out)

    print(HEADER)
    print("|" + "---|" * (HEADER.count("|") - 1))
    todo = [n for n in names if n not in rows]
    for n in names:
        if n in rows:
            print(row_text(rows[n]), flush=True)
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for row in pool.map(lambda n: measure(n, args), todo):
            rows[row["input"]] = row
            save()
            print(row_text(row), flush=True)
    save()
    print()
    print("\n".join(summaries([rows[n] for n in names if n in rows])))


if __name__ == "__main__":
    main()
