"""scripts/realshape_table.py: which holes of a truth mesh its points resolve."""
import importlib.util
import os
import pathlib
import types

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("realshape_table", ROOT / "scripts" / "realshape_table.py")
table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(table)


def square(side):
    corners = [(0.0, 0.0, 0.0), (side, 0.0, 0.0), (side, side, 0.0), (0.0, side, 0.0)]
    return corners, [(0, 1), (1, 2), (2, 3), (3, 0)]


def test_hole_radius_is_a_squares_and_a_triangles_inscribed_circle_and_a_slots_width():
    vertices, loop = square(2.0)
    assert table.hole_radius(vertices, loop, 8.0) == pytest.approx(1.0)
    triangle = [(0.0, 0.0, 0.0), (4.0, 0.0, 0.0), (0.0, 3.0, 0.0)]
    assert table.hole_radius(triangle, [(0, 1), (1, 2), (2, 0)], 12.0) == pytest.approx(1.0)  # 3-4-5
    slot = [(0.0, 0.0, 0.0), (100.0, 0.0, 0.0), (100.0, 2.0, 0.0), (0.0, 2.0, 0.0)]
    assert table.hole_radius(slot, [(0, 1), (1, 2), (2, 3), (3, 0)], 204.0) == pytest.approx(400 / 204)


def grid_with_hole(n, hole):
    """An n x n grid of unit squares in the plane z = 0 without the hole x hole squares at its
    middle: vertices and triangles."""
    vertices = [(float(i), float(j), 0.0) for j in range(n + 1) for i in range(n + 1)]
    lo = (n - hole) // 2
    triangles = []
    for j in range(n):
        for i in range(n):
            if lo <= i < lo + hole and lo <= j < lo + hole:
                continue
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            triangles += [(a, b, c), (a, c, d)]
    return vertices, triangles


def test_boundary_loops_are_the_rim_and_the_hole():
    _, triangles = grid_with_hole(10, 2)
    loops = sorted(table.boundary_loops(triangles), key=len)
    assert [len(loop) for loop in loops] == [8, 40]


@pytest.fixture
def binary():
    path = os.environ.get("ENVCRUST_BINARY", str(ROOT / "build" / "envcrust"))
    if not os.path.exists(path):
        pytest.skip(f"no envcrust binary at {path} (set ENVCRUST_BINARY)")
    return path


@pytest.mark.parametrize("every, unresolved", [(1, 0), (8, 1)])
def test_a_hole_no_wider_than_the_gaps_beside_it_is_counted_as_filled(tmp_path, binary, every, unresolved):
    # A 4 x 4 hole (radius 2) in a 40 x 40 grid: its vertices leave gaps of radius up to 0.71
    # (resolved); every 8th vertex each way, round the hole up to 5 (not resolved).
    vertices, triangles = grid_with_hole(40, 4)
    truth = tmp_path / "truth.off"
    with open(truth, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(triangles)} 0\n")
        f.writelines(f"{x} {y} {z}\n" for x, y, z in vertices)
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in triangles)
    points = tmp_path / "points.xyz"
    with open(points, "w") as f:
        f.writelines(f"{x} {y} {z}\n" for x, y, z in vertices if x % every == 0 and y % every == 0)
    args = types.SimpleNamespace(work=str(tmp_path), timeout=120)
    truth_topo = table.truth_topology(binary, str(truth), args)
    assert truth_topo["topology"] == {"chi": 0, "loops": 2, "orientable": True, "pieces": 1}
    result = table.sampling_resolution(binary, str(truth), str(points), "grid", truth_topo, args)
    assert result["unresolved_holes"] == unresolved
    assert result["topology"]["chi"] == unresolved
    assert result["topology"]["loops"] == 2 - unresolved
    hole = min(result["holes"], key=lambda h: h["length"])
    assert hole["radius"] == pytest.approx(2.0)
    if every == 1:
        assert 0.6 < hole["largest_gap_around"] <= 0.5 ** 0.5 + 1e-9
    else:
        assert 2.0 < hole["largest_gap_around"] <= 32 ** 0.5
