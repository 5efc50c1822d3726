#!/usr/bin/env python3
"""Feed envcrust corrupted input files and report any crash, hang or multi-line error.

Makes truncated and byte-flipped copies of the NURBS examples (examples/nurbs) and of a
built-in surface written as .ply/.off/.obj meshes and as a .ply point set, then runs
`sample` (NURBS files) or `analyze` and `reconstruct` (meshes, points) on each. A run may
succeed (a flipped digit can leave a valid file) or fail with one line naming the file; a
signal, a timeout, or an error of more than one line is reported. Exit status 1 if any.

    scripts/fuzz_inputs.py [--binary build/envcrust] [--variants 10] [--seed 7] [--timeout 300]
"""
import argparse
import glob
import os
import random
import subprocess
import sys
import tempfile


def variants(data, ext, count, rng):
    """Truncated copies, then copies with bytes replaced (text-like bytes for text formats)."""
    out = []
    for _ in range(count):
        out.append(data[:rng.randrange(1, len(data))])
    header_end = data.find(b"end_header")
    for _ in range(count):
        b = bytearray(data)
        for _ in range(rng.choice([1, 3, 10, 50])):
            in_header = header_end > 0 and rng.random() < 0.3
            i = rng.randrange(header_end if in_header else len(b))
            b[i] = rng.randrange(256) if ext == ".ply" else rng.choice(b"0123456789.-eE \n,;[]{}\"fv/#DP")
        out.append(bytes(b))
    return out


def run(cmd, timeout):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout"
    if p.returncode < 0:
        return f"signal {-p.returncode}"
    if p.returncode != 0 and len(p.stderr.strip().splitlines()) != 1:
        return f"exit {p.returncode} with {len(p.stderr.strip().splitlines())} error lines"
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", default="build/envcrust")
    ap.add_argument("--variants", type=int, default=10, help="truncated and flipped copies per file, each")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--timeout", type=float, default=300)
    a = ap.parse_args()
    binary = os.path.abspath(a.binary)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    rng = random.Random(a.seed)
    problems = 0
    runs = 0
    with tempfile.TemporaryDirectory() as tmp:
        sources = sorted(glob.glob(os.path.join(root, "examples", "nurbs", "*")))
        for name in ["m.ply", "m.off", "m.obj"]:
            path = os.path.join(tmp, name)
            subprocess.run([binary, "sample", "torus", "--mesh", "-q", "-o", path], check=True)
            sources.append(path)
        points = os.path.join(tmp, "p.ply")
        subprocess.run([binary, "sample", "torus", "-n", "3000", "--normals", "-q", "-o", points], check=True)
        sources.append(points)
        for source in sources:
            stem, ext = os.path.splitext(os.path.basename(source))
            is_nurbs = ext in (".igs", ".iges", ".json")
            for k, data in enumerate(variants(open(source, "rb").read(), ext, a.variants, rng)):
                path = os.path.join(tmp, f"{stem}_{k}{ext}")
                with open(path, "wb") as f:
                    f.write(data)
                out = os.path.join(tmp, "out.xyz" if is_nurbs else "out.ply")
                commands = [[binary, "sample", path, "-n", "2000", "-q", "-o", out]] if is_nurbs else [
                    [binary, "analyze", path], [binary, "reconstruct", path, "-q", "-o", out]]
                for cmd in commands:
                    runs += 1
                    problem = run(cmd, a.timeout)
                    if problem:
                        problems += 1
                        kept = os.path.join(os.getcwd(), f"fuzz_{stem}_{k}{ext}")
                        with open(kept, "wb") as f:
                            f.write(data)
                        print(f"{cmd[1]} {kept}: {problem}")
    print(f"{runs} runs, {problems} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
