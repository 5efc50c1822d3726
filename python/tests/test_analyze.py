"""envcrust.analyze() on meshes whose topology is known."""
import numpy as np
import pytest

import envcrust


def strip(twists, n=40):
    """A band around a circle of radius 2, width 0.5: an annulus (twists 0) or a Moebius strip (1)."""
    vertices, faces = [], []
    for i in range(n):
        t = 2 * np.pi * i / n
        for s in (-0.25, 0.25):
            half = twists * t / 2
            r = 2 + s * np.cos(half)
            vertices.append((r * np.cos(t), r * np.sin(t), s * np.sin(half)))
    for i in range(n):
        a, b = 2 * i, 2 * i + 1
        if i + 1 < n:
            c, d = 2 * i + 2, 2 * i + 3
        else:  # the last quad closes the band, crossed over when it is twisted
            c, d = (1, 0) if twists % 2 else (0, 1)
        faces += [(a, c, b), (b, c, d)]
    return np.array(vertices), np.array(faces)


def test_moebius_strip_mesh():
    report = envcrust.analyze(*strip(1))
    assert report["euler_characteristic"] == 0
    assert report["boundary_loops"] == 1
    assert report["is_orientable"] is False
    assert report["components"] == 1
    assert report["is_manifold"] is True
    assert report["loops"][0]["knot"]["type"] == "unknot"


def test_annulus_mesh():
    report = envcrust.analyze(*strip(0))
    assert (report["euler_characteristic"], report["boundary_loops"], report["is_orientable"]) == (0, 2, True)
    assert report["genus"] == 0
    assert abs(report["linking"][0]["linking_number"]) == 0


def test_tetrahedron_is_a_closed_sphere():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    report = envcrust.analyze(vertices, faces)
    assert (report["euler_characteristic"], report["boundary_loops"], report["is_closed"]) == (2, 0, True)
    assert (report["vertices"], report["edges"], report["faces"]) == (4, 6, 4)


def test_distances_to_reference_points():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    report = envcrust.analyze(vertices, [[0, 1, 2]], reference=[[0.25, 0.25, 0.5]])
    assert report["distance"]["reference_to_mesh"]["max"] == pytest.approx(0.5, abs=1e-9)


def test_face_index_out_of_range_is_refused():
    with pytest.raises(ValueError, match="^faces: row 0 has vertex index 3, out of range \\(3 vertices\\)$"):
        envcrust.analyze(np.eye(3), [[0, 1, 3]])
