"""envcrust.reconstruct(classification=..., classes=...): the CLI's --classes on numpy arrays."""
import json
import subprocess

import numpy as np
import pytest

import envcrust

GROUND, ROOF = 2, 6


@pytest.fixture(scope="module")
def two_classes():
    """A ground hemisphere (2,500 points, class 2) under a roof one 5 higher (400 points, class 6),
    as the CLI's LAS test builds them, with the classes as read_points gives them (float32)."""
    ground = envcrust.sample("hemisphere", 2500, seed=1)
    roof = envcrust.sample("hemisphere", 400, seed=2) + [0.0, 0.0, 5.0]
    points = np.vstack([ground, roof])
    classification = np.r_[np.full(2500, GROUND), np.full(400, ROOF)].astype(np.float32)
    return points, classification


def topology(result):
    a = result.report["analysis"]
    return a["euler_characteristic"], a["boundary_loops"], a["components"]


def test_classes_keep_only_the_ground_with_its_colours(two_classes):
    points, classification = two_classes
    colours = np.where(classification[:, None] == GROUND, [[120, 90, 30]], [[200, 0, 0]]).astype(np.uint8)
    result = envcrust.reconstruct(points, colors=colours, classification=classification, classes=[GROUND])
    assert result.report["notes"][0] == "kept the 2500 of 2900 points of class 2"
    assert topology(result) == (1, 1, 1)  # one disc
    assert result.report["checks"]["passed"] is True
    assert result.vertices[:, 2].max() < 1.01  # nothing of the roof
    assert np.all(result.colors == [120, 90, 30])


def test_classes_keep_only_the_roof_given_as_one_integer_class(two_classes):
    points, classification = two_classes
    result = envcrust.reconstruct(points, classification=classification.astype(np.int64), classes=np.int64(ROOF))
    assert result.report["notes"][0] == "kept the 400 of 2900 points of class 6"
    assert topology(result) == (1, 1, 1)
    assert result.vertices[:, 2].min() > 4.99


def test_classes_listing_every_class_keep_every_point(two_classes):
    points, classification = two_classes
    both = envcrust.reconstruct(points, classification=classification, classes=(ROOF, GROUND))
    assert both.report["notes"][0] == "kept the 2900 of 2900 points of class 6 or 2"
    unfiltered = envcrust.reconstruct(points, classification=classification)
    assert not any(note.startswith("kept the") for note in unfiltered.report["notes"])
    assert topology(both) == topology(unfiltered) == (2, 2, 2)  # two discs
    assert np.array_equal(both.faces, unfiltered.faces)


def test_classes_no_point_has_are_refused_naming_the_classes_present(two_classes):
    points, classification = two_classes
    with pytest.raises(envcrust.InvalidInput) as error:
        envcrust.reconstruct(points, classification=classification, classes=[7, 9])
    assert str(error.value) == \
        "points: no point is of class 7 or 9 (the points' classes: 2 (2500 points), 6 (400 points))"


def test_classes_without_a_classification_are_refused(two_classes):
    points, _ = two_classes
    with pytest.raises(envcrust.InvalidInput) as error:
        envcrust.reconstruct(points, classes=[2, 6])
    assert str(error.value) == ("points: the points have no classification to choose classes 2, 6 from "
                                "(LAS files have one, point files a column named 'classification')")


def test_classes_agree_with_the_cli_on_a_point_file(two_classes, cli, tmp_path):
    points, classification = two_classes
    path = tmp_path / "classes.txt"
    np.savetxt(path, np.c_[points, classification], fmt="%.17g", header="x y z classification", comments="")
    read = envcrust.read_points(str(path))
    ours = envcrust.reconstruct(read["points"], classification=read["scalars"]["classification"], classes=[GROUND])
    out = subprocess.run([cli, "reconstruct", str(path), "--classes", "2", "-o", str(tmp_path / "g.ply"), "--json"],
                         capture_output=True, text=True, check=True)
    theirs = json.loads(out.stdout)
    assert ours.report["notes"] == theirs["notes"]
    assert ours.report["input_points"] == theirs["input_points"]
    for key in ("euler_characteristic", "boundary_loops", "components", "vertices", "faces"):
        assert ours.report["analysis"][key] == theirs["analysis"][key], key
    with pytest.raises(envcrust.InvalidInput) as error:
        envcrust.reconstruct(read["points"], classification=read["scalars"]["classification"], classes=[7])
    refused = subprocess.run([cli, "reconstruct", str(path), "--classes", "7", "-o", str(tmp_path / "x.ply")],
                             capture_output=True, text=True)
    assert refused.returncode == 1
    assert refused.stderr == f"envcrust: error: {path}{str(error.value).removeprefix('points')}\n"


@pytest.mark.parametrize("classes", [[], [256], [-1], "2", [2.0], True, [2, None]])
def test_classes_bad_values_are_value_errors(two_classes, classes):
    points, classification = two_classes
    with pytest.raises(ValueError) as error:
        envcrust.reconstruct(points, classification=classification, classes=classes)
    assert str(error.value) == ("classes must be a class number or a list of them, whole numbers in 0..255; "
                                f"None keeps every point (got {classes!r})")


@pytest.mark.parametrize("classification, message", [
    (np.zeros((100, 2)), "classification must be an array of shape (n,), got shape (100, 2)"),
    (np.zeros(99), "classification must have 100 values (one per point), got 99"),
    (np.array(["a"] * 100), "classification must hold whole numbers, got dtype <U1"),
    (np.r_[np.zeros(7), 1.5, np.zeros(92)], "classification: row 7 has 1.5, not a whole number within +-2^24"),
    (np.r_[np.nan, np.zeros(99)], "classification: row 0 has nan, not a whole number within +-2^24"),
])
def test_classes_bad_classification_arrays_are_refused(classification, message):
    points = envcrust.sample("hemisphere", 100, seed=1)
    with pytest.raises(ValueError) as error:
        envcrust.reconstruct(points, classification=classification, classes=[2])
    assert str(error.value) == message
