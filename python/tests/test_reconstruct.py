"""envcrust.reconstruct(): the result, its report against the CLI's, options, progress and errors."""
import json
import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import envcrust


def triangle_set(faces):
    """Each triangle with its smallest index first, its winding kept."""
    return {tuple(np.roll(t, -int(np.argmin(t)))) for t in np.asarray(faces)}


@pytest.fixture(scope="module")
def moebius(moebius_points):
    return envcrust.reconstruct(moebius_points)


def test_moebius_strip_is_non_orientable_with_one_boundary_loop(moebius):
    analysis = moebius.report["analysis"]
    assert analysis["is_orientable"] is False
    assert analysis["boundary_loops"] == 1
    assert analysis["euler_characteristic"] == 0
    assert analysis["is_manifold"] is True
    assert moebius.report["checks"] == {"passed": True, "failed": [], "uncovered_patches": 0}
    assert moebius.vertices.shape == (analysis["vertices"], 3)
    assert moebius.vertices.dtype == np.float64
    assert moebius.faces.shape == (analysis["faces"], 3)
    assert moebius.faces.min() >= 0 and moebius.faces.max() < len(moebius.vertices)
    assert moebius.normals.shape == moebius.vertices.shape
    assert moebius.colors is None
    assert "non-orientable" in repr(moebius)


def test_moebius_report_agrees_with_the_cli(moebius_points, moebius, cli, tmp_path):
    points_file = tmp_path / "moebius.xyz"
    np.savetxt(points_file, moebius_points, fmt="%.17g")
    # The file holds the very doubles the module was given.
    assert np.array_equal(envcrust.read_points(str(points_file))["points"], moebius_points)
    out = subprocess.run([cli, "reconstruct", str(points_file), "-o", str(tmp_path / "m.ply"), "--json"],
                         capture_output=True, text=True, check=True)
    theirs = json.loads(out.stdout)
    ours = moebius.report
    for key in ("euler_characteristic", "boundary_loops", "is_orientable", "vertices", "faces", "edges",
                "components", "is_manifold"):
        assert ours["analysis"][key] == theirs["analysis"][key], key
    assert ours["envelope"]["rho"] == pytest.approx(theirs["envelope"]["rho"], rel=1e-12)
    assert ours["envelope"]["samples"] == theirs["envelope"]["samples"]
    assert ours["input_points"] == theirs["input_points"] == 10000
    assert ours["checks"] == theirs["checks"]
    assert ours["boundary_check"]["is_consistent"] == theirs["boundary_check"]["is_consistent"]
    # The mesh the CLI wrote is the module's, vertex for vertex (PLY stores floats), with the
    # same triangles wound the same way (compared as sets: their order is not what is checked).
    vertices, faces = envcrust.read_mesh(str(tmp_path / "m.ply"))
    assert np.allclose(vertices, moebius.vertices, atol=1e-6)
    assert triangle_set(faces) == triangle_set(moebius.faces)


def test_colours_reach_the_nearest_vertices():
    points = envcrust.sample("hemisphere", 3000, seed=2)
    colours = np.where(points[:, [0]] > 0, [[200, 30, 10]], [[10, 40, 220]]).astype(np.uint8)
    result = envcrust.reconstruct(points, colors=colours, threads=2)
    assert result.report["analysis"]["boundary_loops"] == 1
    assert result.report["analysis"]["euler_characteristic"] == 1
    assert result.report["threads"] == 2
    assert result.colors.shape == result.vertices.shape and result.colors.dtype == np.uint8
    far_from_the_cut = np.abs(result.vertices[:, 0]) > 0.05
    expected = np.where(result.vertices[:, [0]] > 0, [[200, 30, 10]], [[10, 40, 220]])
    assert np.array_equal(result.colors[far_from_the_cut], expected[far_from_the_cut])


def test_points_far_from_the_origin_come_back_in_their_own_coordinates():
    points = envcrust.sample("hemisphere", 3000, seed=8)
    offset = np.array([500000.0, 5000000.0, 100.0])  # UTM-like metres
    near = envcrust.reconstruct(points)
    far = envcrust.reconstruct(points + offset)
    assert far.report["input_origin"] is not None
    # The move rounds the samples by ~1e-9 (the doubles' step at 5e6), which may flip the
    # diagonal of a near-cospherical quad: the meshes agree but for a few triangles.
    assert abs(len(far.faces) - len(near.faces)) <= 0.001 * len(near.faces)
    # The same surface to within 1e-6 of the diagonal: each vertex, moved back, is one of the other's.
    diagonal = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
    moved_back = far.vertices - offset
    nearest = [np.sqrt(((near.vertices - v) ** 2).sum(axis=1)).min() for v in moved_back]
    assert max(nearest) < 1e-6 * diagonal
    assert far.report["analysis"]["euler_characteristic"] == near.report["analysis"]["euler_characteristic"] == 1


def test_float_colours_in_0_1_are_scaled_to_bytes():
    points = envcrust.sample("hemisphere", 2000, seed=3)
    result = envcrust.reconstruct(points, colors=np.full((2000, 3), 0.5))
    assert np.all(result.colors == 128)


def test_given_normals_are_used():
    points, normals = envcrust.sample("hemisphere", 2000, seed=4, normals=True)
    result = envcrust.reconstruct(points, normals)
    assert not any("estimated" in note for note in result.report["notes"])
    assert result.report["analysis"]["boundary_loops"] == 1


def test_options_reach_the_run():
    points = envcrust.sample("hemisphere", 2000, seed=5)
    result = envcrust.reconstruct(points, rho=0.15, spacing=0.3, seed=7, method="envelope", analysis=False)
    assert result.report["envelope"]["rho"] == 0.15
    assert "analysis" not in result.report and "checks" not in result.report
    crust = envcrust.reconstruct(points, method="powercrust")
    assert crust.report["method"] == "powercrust"


def test_closed_and_sample_meshing_options():
    closed = envcrust.reconstruct(envcrust.sample("sphere", 3000, seed=1), detect_boundary=False)
    assert (closed.report["analysis"]["euler_characteristic"], closed.report["analysis"]["boundary_loops"]) == (2, 0)
    meshed = envcrust.reconstruct(envcrust.sample("hemisphere", 3000, seed=1), extract="samples")
    assert meshed.report["sample_meshing"]["is_kept"] is True
    assert len(meshed.vertices) == 3000
    assert meshed.report["analysis"]["euler_characteristic"] == 1


def test_library_option_checks_raise_invalid_options():
    with pytest.raises(envcrust.InvalidOptions, match="^EnvelopeOptions::spacing_rel_rho out of range \\(got 10\\)$"):
        envcrust.reconstruct(envcrust.sample("hemisphere", 500, seed=1), spacing=10)


def test_progress_reports_each_stage_in_order():
    seen = []
    envcrust.reconstruct(envcrust.sample("hemisphere", 2000, seed=6), progress=lambda s, f: seen.append((s, f)))
    stages = [s for s, _ in seen]
    assert stages[0].startswith("input")
    for stage in ("envelope", "medial sheet", "analysis"):
        assert stage in stages, stage
    assert stages.index("envelope") < stages.index("medial sheet") < stages.index("analysis")
    assert all(0.0 <= f <= 1.0 for _, f in seen)


def test_an_exception_in_the_progress_callback_cancels_the_run():
    seen = []

    def stop_at_the_envelope(stage, fraction):
        seen.append(stage)
        if stage == "envelope":
            raise RuntimeError("stopped by the callback")

    with pytest.raises(RuntimeError, match="^stopped by the callback$"):
        envcrust.reconstruct(envcrust.sample("hemisphere", 2000, seed=6), progress=stop_at_the_envelope)
    assert seen[-1] == "envelope" and "medial sheet" not in seen


def test_ctrl_c_cancels_a_run_with_keyboard_interrupt(tmp_path):
    # The child signals itself from a second thread while the stages run without the GIL; the
    # next progress report runs Python's handler and the run ends with KeyboardInterrupt.
    script = textwrap.dedent("""
        import os, signal, threading, envcrust
        points = envcrust.sample("moebius", 10000, seed=1)
        stages = []
        def interrupt_once_started(stage, fraction):
            stages.append(stage)
            if len(stages) == 1:
                threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()
        try:
            envcrust.reconstruct(points, progress=interrupt_once_started)
            print("finished after", stages)
        except KeyboardInterrupt:
            print("interrupted after", len(stages), "reports, last", stages[-1])
    """)
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300,
                         env=dict(os.environ))
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("interrupted after"), out.stdout
    assert "last analysis" not in out.stdout


def test_unknown_option_is_a_type_error_naming_it():
    with pytest.raises(TypeError, match="^reconstruct\\(\\) got an unexpected keyword argument 'rhoo'$"):
        envcrust.reconstruct(np.zeros((10, 3)), rhoo=0.1)


@pytest.mark.parametrize("keyword, value, message", [
    ("rho", -1, "rho must be 'auto', None or a positive number (got -1)"),
    ("rho", "big", "rho must be 'auto', None or a positive number (got 'big')"),
    ("method", "poisson", "method must be one of 'envelope', 'powercrust' (got 'poisson')"),
    ("threads", -2, "threads must be a whole number >= 0, 0 for every core (got -2)"),
    ("seed", 1.5, "seed must be a whole number >= 0 (got 1.5)"),
])
def test_bad_option_values_are_value_errors(keyword, value, message):
    with pytest.raises(ValueError) as error:
        envcrust.reconstruct(np.zeros((10, 3)), **{keyword: value})
    assert str(error.value) == message


def test_wrong_option_type_is_a_type_error():
    with pytest.raises(TypeError, match="^spacing has the wrong type \\(got 'wide'\\)$"):
        envcrust.reconstruct(np.zeros((10, 3)), spacing="wide")


@pytest.mark.parametrize("points, message", [
    (np.zeros((10, 2)), "points must be an array of shape (n, 3), got shape (10, 2)"),
    (np.zeros(12), "points must be an array of shape (n, 3), got shape (12,)"),
    (np.array([["a", "b", "c"]]), "points must hold numbers, got dtype <U1"),
    (np.array([[0, 0, 0], [1, np.nan, 0]]), "points: row 1 has a non-finite coordinate"),
])
def test_points_of_the_wrong_shape_or_values_are_refused(points, message):
    with pytest.raises(ValueError) as error:
        envcrust.reconstruct(points)
    assert str(error.value) == message


def test_normals_and_colours_need_one_row_per_point():
    points = envcrust.sample("hemisphere", 100, seed=1)
    with pytest.raises(ValueError, match="^normals must have 100 rows \\(one per point\\), got 99$"):
        envcrust.reconstruct(points, normals=np.ones((99, 3)))
    with pytest.raises(ValueError, match="^colors: row 0 has a value outside 0..255 \\(integer colours\\)$"):
        envcrust.reconstruct(points, colors=np.full((100, 3), 300))


def test_degenerate_points_raise_the_libraries_message():
    with pytest.raises(envcrust.DegenerateInput) as error:
        envcrust.reconstruct([[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    assert str(error.value).startswith("points: need at least 5 distinct points, got 3")
    assert isinstance(error.value, envcrust.InvalidInput)
    assert isinstance(error.value, ValueError)
    assert isinstance(error.value, envcrust.Error)


def test_a_rho_the_sampling_cannot_support_is_refused_as_the_cli_refuses_it(moebius_points, cli, tmp_path):
    with pytest.raises(envcrust.InvalidInput) as error:
        envcrust.reconstruct(moebius_points, rho=0.001)
    ours = str(error.value)
    assert ours.startswith("points: rho 0.001 is more than the sampling supports: ")
    assert ours.endswith("(or rho='auto'), or force=True to run it anyway")
    points_file = tmp_path / "points.xyz"
    np.savetxt(points_file, moebius_points, fmt="%.17g")
    out = subprocess.run([cli, "reconstruct", str(points_file), "-o", str(tmp_path / "m.ply"), "--rho", "0.001"],
                         capture_output=True, text=True)
    assert out.returncode == 1
    theirs = out.stderr.strip().removeprefix(f"envcrust: error: {points_file}")
    assert theirs.replace("--rho auto", "rho='auto'").replace("--rho ", "rho=").replace("--force", "force=True") \
        == ours.removeprefix("points")
