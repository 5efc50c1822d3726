"""envcrust.sample() and envcrust.surfaces(): the built-in surfaces."""
import subprocess

import numpy as np
import pytest

import envcrust


def test_points_are_those_of_the_cli(cli, tmp_path):
    path = tmp_path / "m.xyz"
    subprocess.run([cli, "sample", "moebius", "-n", "500", "--seed", "3", "-q", "-o", str(path)], check=True)
    assert np.array_equal(envcrust.sample("moebius", 500, seed=3), envcrust.read_points(str(path))["points"])


def test_same_seed_same_points_and_normals_are_unit():
    a = envcrust.sample("torus", 300, seed=9)
    assert a.shape == (300, 3)
    assert np.array_equal(a, envcrust.sample("torus", 300, seed=9))
    assert not np.array_equal(a, envcrust.sample("torus", 300, seed=10))
    points, normals = envcrust.sample("torus", 300, seed=9, normals=True)
    assert np.array_equal(points, a)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1)


def test_surfaces_list_their_expected_topology():
    listed = envcrust.surfaces()
    assert listed["moebius"]["expected"]["is_orientable"] is False
    assert listed["moebius"]["expected"]["boundary_loops"] == 1
    assert listed["trefoil-ribbon"]["expected"]["abs_linking_number"] == 3


def test_unknown_surface_names_the_known_ones():
    with pytest.raises(envcrust.InvalidInput) as error:
        envcrust.sample("klein", 10)
    assert str(error.value).startswith("unknown surface 'klein' (known: ")
    assert "moebius" in str(error.value)
