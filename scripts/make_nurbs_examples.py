#!/usr/bin/env python3
"""Write the NURBS example patches of examples/nurbs/ (IGES entity 128 and NURBS-Python JSON).

    python3 scripts/make_nurbs_examples.py [OUT_DIR]      # default examples/nurbs

trefoil-ribbon.igs  a periodic cubic B-spline through a trefoil's shape, extruded 0.5 along z:
                    a ribbon whose two edges are linked trefoils (a CAD version of the
                    paper's Figure 1)
moebius-band.json   a ruled band around the rational unit circle whose ruling turns half
                    round: a Moebius strip
sphere.igs          the unit sphere, a rational circle revolved by a rational half circle
plate-with-hole.igs a curved bicubic plate trimmed by a round hole (IGES trimmed surface 144)
open-box.igs        five bilinear squares, the unit cube without its top: a model of several
                    patches meeting at right angles (a disc with one rim loop)
cup.igs             a rational tube and the disc closing its bottom (a pole at its centre),
                    meeting at a right angle: a disc
tube-quarters.json  four rational quarter tubes joined smoothly: an open cylinder
"""
import json
import math
import os
import sys

H = math.sqrt(2) / 2
CIRCLE = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
CIRCLE_W = [1, H, 1, H, 1, H, 1, H, 1]
CIRCLE_KNOTS = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]


class Patch:
    """Degrees, knots, and the control net with weights, u index fastest."""

    def __init__(self, degree_u, degree_v, knots_u, knots_v, count_u, count_v, points, weights):
        self.degree_u, self.degree_v = degree_u, degree_v
        self.knots_u, self.knots_v = knots_u, knots_v
        self.count_u, self.count_v = count_u, count_v
        self.points, self.weights = points, weights


def trefoil_ribbon(samples=24):
    def trefoil(s):
        return (math.sin(s) + 2 * math.sin(2 * s), math.cos(s) - 2 * math.cos(2 * s), -math.sin(3 * s))
    ring = [trefoil(2 * math.pi * k / samples) for k in range(samples)]
    ring += ring[:3]  # a periodic cubic: the first 3 control points repeated at the end
    count_u = len(ring)
    points = [(x, y, z + dz) for dz in (0.0, 0.5) for (x, y, z) in ring]
    return Patch(3, 1, list(range(count_u + 4)), [0, 0, 1, 1], count_u, 2, points, [1.0] * len(points))


def moebius_band(half_width=0.3):
    points, weights = [], []
    for v in (-half_width, half_width):
        for i, (x, y) in enumerate(CIRCLE):
            phi = math.pi / 4 * i
            c = math.cos(phi / 2)
            points.append((x + v * c * math.cos(phi), y + v * c * math.sin(phi), v * math.sin(phi / 2)))
            weights.append(CIRCLE_W[i])
    return Patch(2, 1, CIRCLE_KNOTS, [-1, -1, 1, 1], 9, 2, points, weights)


def sphere():
    half = [(0, -1), (1, -1), (1, 0), (1, 1), (0, 1)]
    half_w = [1, H, 1, H, 1]
    points, weights = [], []
    for j, (r, z) in enumerate(half):
        for i, (x, y) in enumerate(CIRCLE):
            points.append((x * r, y * r, z))
            weights.append(CIRCLE_W[i] * half_w[j])
    return Patch(2, 2, CIRCLE_KNOTS, [0, 0, 0, 0.5, 0.5, 1, 1, 1], 9, 5, points, weights)


def number(x):
    return repr(float(x)) if x != int(x) else str(int(x))


def surface_values(patch):
    """The parameters of an IGES entity 128 (after the type number)."""
    values = [patch.count_u - 1, patch.count_v - 1, patch.degree_u, patch.degree_v, 0, 0, 0, 0, 0]
    values += patch.knots_u + patch.knots_v + patch.weights
    for p in patch.points:
        values += list(p)
    values += [patch.knots_u[patch.degree_u], patch.knots_u[patch.count_u],
               patch.knots_v[patch.degree_v], patch.knots_v[patch.count_v]]
    return values


def write_iges(entities, path, title):
    """entities: (type, parameter values) in order; the k-th is at directory line 2k + 1."""
    def record(data, section, sequence):
        return data.ljust(72)[:72] + "%s%7d\n" % (section, sequence)

    def entry(*values):
        return "".join("%8s" % v for v in values)

    name = os.path.basename(path)
    out = record(title, "S", 1) + record("1H,,1H;,%dH%s,%dH%s;" % (len(title), title, len(name), name), "G", 1)
    directory, parameters = "", ""
    sequence = 0
    for k, (kind, values) in enumerate(entities):
        fields = [str(kind)] + [number(v) for v in values]
        lines = [""]
        for i, f in enumerate(fields):
            f += ";" if i + 1 == len(fields) else ","
            if len(lines[-1]) + len(f) > 64:
                lines.append("")
            lines[-1] += f
        directory += record(entry(kind, sequence + 1, 0, 0, 0, 0, 0, 0, "00000000"), "D", 2 * k + 1)
        directory += record(entry(kind, 0, 0, len(lines), 0), "D", 2 * k + 2)
        for line in lines:
            sequence += 1
            parameters += record(line.ljust(64) + "%8d" % (2 * k + 1), "P", sequence)
    out += directory + parameters + record("S%7dG%7dD%7dP%7d" % (1, 1, 2 * len(entities), sequence), "T", 1)
    with open(path, "w") as f:
        f.write(out)


def plate_with_hole():
    """A gently curved square plate (bicubic, z = 0.15 at its middle) trimmed by a round hole:
    the surface entity 128, the trimmed surface 144 (outer boundary the domain's border, one
    hole), the hole's curve on surface 142 and its parameter-plane circle 100."""
    heights = [0, 0, 0, 0, 0, 0.2, 0.2, 0, 0, 0.2, 0.2, 0, 0, 0, 0, 0]
    points = [(i / 3, j / 3, heights[i + 4 * j]) for j in range(4) for i in range(4)]
    plate = Patch(3, 3, [0, 0, 0, 0, 1, 1, 1, 1], [0, 0, 0, 0, 1, 1, 1, 1], 4, 4, points, [1.0] * 16)
    return [(128, surface_values(plate)),
            (144, [1, 0, 1, 0, 5]),              # base 128, N1 = 0 (border), one hole at line 5
            (142, [1, 1, 7, 0, 1]),              # the hole on surface 1, its parameter curve at line 7
            (100, [0, 0.5, 0.5, 0.8, 0.5, 0.8, 0.5])]  # a full circle, centre (0.5, 0.5), radius 0.3


def bilinear(a, b, c, d):
    """The flat quadrilateral a b c d (counter-clockwise), degree 1 both ways."""
    return Patch(1, 1, [0, 0, 1, 1], [0, 0, 1, 1], 2, 2, [a, b, d, c], [1.0] * 4)


def open_box():
    """The unit cube's bottom and four sides, each face wound outward."""
    corners = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    c = lambda x, y, z: corners[x + 2 * y + 4 * z]
    faces = [(c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)),   # bottom, facing -z
             (c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)),   # y = 0
             (c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)),   # x = 1
             (c(1, 1, 0), c(0, 1, 0), c(0, 1, 1), c(1, 1, 1)),   # y = 1
             (c(0, 1, 0), c(0, 0, 0), c(0, 0, 1), c(0, 1, 1))]   # x = 0
    return [bilinear(*f) for f in faces]


def revolved(profile, profile_weights, knots_v):
    """The rational unit circle (u) swept along a profile of (radius, z) points (v)."""
    points, weights = [], []
    for (r, z), w in zip(profile, profile_weights):
        for i, (x, y) in enumerate(CIRCLE):
            points.append((x * r, y * r, z))
            weights.append(CIRCLE_W[i] * w)
    return Patch(2, len(knots_v) - len(profile) - 1, CIRCLE_KNOTS, knots_v, 9, len(profile), points, weights)


def cup():
    """A tube of radius 1 from z = 0 to 1, and the disc at z = 0 (its centre a pole)."""
    tube = revolved([(1, 0), (1, 1)], [1, 1], [0, 0, 1, 1])
    bottom = revolved([(0, 0), (1, 0)], [1, 1], [0, 0, 1, 1])
    return [tube, bottom]


def tube_quarters():
    """The open cylinder of radius 1, z in [0, 1], as four rational quarter tubes."""
    patches = []
    for q in range(4):
        points, weights = [], []
        for z in (0, 1):
            for i in range(3):
                x, y = CIRCLE[2 * q + i]
                points.append((x, y, z))
                weights.append(CIRCLE_W[2 * q + i])
        patches.append(Patch(2, 1, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], 3, 2, points, weights))
    return patches


def write_json(patches, path):
    # NURBS-Python lists the control points v fastest.
    entries = [json_entry(p) for p in (patches if isinstance(patches, list) else [patches])]
    with open(path, "w") as f:
        json.dump({"shape": {"type": "surface", "count": len(entries), "data": entries}}, f, indent=1)
        f.write("\n")


def json_entry(patch):
    order = [i + patch.count_u * j for i in range(patch.count_u) for j in range(patch.count_v)]
    return {"type": "spline", "rational": True, "dimension": 3, "degree_u": patch.degree_u,
            "degree_v": patch.degree_v, "knotvector_u": patch.knots_u, "knotvector_v": patch.knots_v,
            "size_u": patch.count_u, "size_v": patch.count_v,
            "control_points": {"points": [list(patch.points[k]) for k in order],
                               "weights": [patch.weights[k] for k in order]}}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "examples", "nurbs")
    os.makedirs(out, exist_ok=True)
    write_iges([(128, surface_values(trefoil_ribbon()))], os.path.join(out, "trefoil-ribbon.igs"),
               "envcrust trefoil ribbon")
    write_json(moebius_band(), os.path.join(out, "moebius-band.json"))
    write_iges([(128, surface_values(sphere()))], os.path.join(out, "sphere.igs"), "envcrust unit sphere")
    write_iges(plate_with_hole(), os.path.join(out, "plate-with-hole.igs"), "envcrust plate with a hole")
    write_iges([(128, surface_values(p)) for p in open_box()], os.path.join(out, "open-box.igs"),
               "envcrust open box")
    write_iges([(128, surface_values(p)) for p in cup()], os.path.join(out, "cup.igs"), "envcrust cup")
    write_json(tube_quarters(), os.path.join(out, "tube-quarters.json"))
    print("wrote trefoil-ribbon.igs, moebius-band.json, sphere.igs, plate-with-hole.igs, open-box.igs, cup.igs,",
          "tube-quarters.json to", os.path.normpath(out))


if __name__ == "__main__":
    main()
