"""read_points, read_mesh and write_mesh: round trips and the readers' messages."""
import numpy as np
import pytest

import envcrust


@pytest.fixture
def square():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]], dtype=float)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    return vertices, faces


@pytest.mark.parametrize("extension", ["ply", "off", "obj"])
def test_mesh_round_trip(square, tmp_path, extension):
    path = str(tmp_path / f"square.{extension}")
    envcrust.write_mesh(path, *square)
    vertices, faces = envcrust.read_mesh(path)
    assert np.array_equal(faces, square[1])
    assert np.allclose(vertices, square[0], atol=1e-6)


def test_colours_round_trip_through_ply(square, tmp_path):
    path = str(tmp_path / "square.ply")
    colours = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255], [10, 20, 30]], dtype=np.uint8)
    envcrust.write_mesh(path, *square, colors=colours)
    read = envcrust.read_points(path)
    assert np.array_equal(read["colors"], colours)
    assert read["normals"] is None


def test_point_file_with_normals_and_intensity(tmp_path):
    path = tmp_path / "p.txt"
    path.write_text("x y z nx ny nz intensity\n0 0 0 0 0 1 5\n1 0 0 0 0 2 7\n")
    read = envcrust.read_points(str(path))
    assert np.array_equal(read["points"], [[0, 0, 0], [1, 0, 0]])
    assert np.array_equal(read["normals"], [[0, 0, 1], [0, 0, 2]])  # as the file gives them
    assert np.array_equal(read["scalars"]["intensity"], [5, 7])


def test_bad_point_file_raises_the_readers_message(tmp_path):
    path = tmp_path / "bad.xyz"
    path.write_text("0 0 0\n1 2\n")
    with pytest.raises(envcrust.IoError) as error:
        envcrust.read_points(str(path))
    assert str(error.value).startswith(f"{path}:2: ")
    assert isinstance(error.value, OSError)


def test_missing_file_and_unknown_extension(square, tmp_path):
    with pytest.raises(envcrust.IoError, match="nothing.ply"):
        envcrust.read_mesh(str(tmp_path / "nothing.ply"))
    with pytest.raises(envcrust.IoError) as error:
        envcrust.write_mesh(str(tmp_path / "x.abc"), *square)
    assert str(error.value).startswith(f"{tmp_path / 'x.abc'}: unknown extension '.abc'")
    assert not (tmp_path / "x.abc").exists()
