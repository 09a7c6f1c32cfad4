"""detect, reconstruct, mesh and fit's inliers through the module, on clouds sampled from known
models: the expected values are the generating models' parameters and memberships."""
import json

import numpy as np
import pytest

import implicitfit
from conftest import spins_during

PLANE = {"type": "plane", "normal": [0, 0, 1], "offset": 0}
SPHERE = {"type": "sphere", "center": [3, 0, 1.5], "radius": 1}
NOISE = 0.002


def model(root):
    return implicitfit.Model.from_json(
        json.dumps({"format": "implicitfit-model", "version": 1, "root": root}))


@pytest.fixture(scope="module")
def plane_and_sphere():
    """3000 points on the plane z = 0 (x, y in [-1, 1]), then 3000 on the sphere: the truth
    label of point i is 0 (plane) for i < 3000, 1 (sphere) after."""
    p1, n1 = implicitfit.sample(model(PLANE), 3000, noise=NOISE, seed=1)
    p2, n2 = implicitfit.sample(model(SPHERE), 3000, noise=NOISE, seed=2)
    truth = np.repeat([0, 1], [len(p1), len(p2)])
    return np.vstack([p1, p2]), np.vstack([n1, n2]), truth


def iou(a, b):
    a, b = set(a.tolist()), set(b.tolist())
    return len(a & b) / len(a | b)


def best_match(result, members):
    return max(result.primitives, key=lambda p: iou(p.indices, members))


@pytest.mark.parametrize("with_normals", [True, False])
def test_detect_recovers_the_plane_and_the_sphere(plane_and_sphere, with_normals):
    points, normals, truth = plane_and_sphere
    result = implicitfit.detect(points, normals if with_normals else None, seed=1)
    assert isinstance(result, implicitfit.DetectResult)
    assert len(result.primitives) >= 2
    plane = best_match(result, np.flatnonzero(truth == 0))
    sphere = best_match(result, np.flatnonzero(truth == 1))
    assert plane.kind == "plane" and plane.model["type"] == "plane"
    assert sphere.kind == "sphere" and sphere.model["type"] == "sphere"
    assert iou(plane.indices, np.flatnonzero(truth == 0)) > 0.95
    assert iou(sphere.indices, np.flatnonzero(truth == 1)) > 0.95
    # The plane's normal is +-z (its sign is the side the normals show), its offset 0.
    normal = np.array(plane.model["normal"])
    assert abs(abs(normal[2]) - 1) < 1e-4
    assert abs(plane.model["offset"]) < 5 * NOISE
    assert np.linalg.norm(np.array(sphere.model["center"]) - SPHERE["center"]) < 5 * NOISE
    assert abs(sphere.model["radius"] - SPHERE["radius"]) < 5 * NOISE
    for p in (plane, sphere):
        assert NOISE / 2 < p.rms_distance < 2 * NOISE
        assert p.indices.dtype == np.int64 and np.all(np.diff(p.indices) > 0)


def test_detect_labels_indices_and_report_agree(plane_and_sphere):
    points, normals, _ = plane_and_sphere
    result = implicitfit.detect(points, normals)
    assert result.labels.shape == (len(points),) and result.labels.dtype == np.int64
    assert result.labels.min() >= -1 and result.labels.max() < len(result.primitives)
    for k, p in enumerate(result.primitives):
        assert np.array_equal(np.flatnonzero(result.labels == k), p.indices)
        assert p.name == f"p{k}"
    assert result.report["primitives"] == len(result.primitives)
    assert result.report["unassigned"] == int(np.sum(result.labels == -1))
    assert result.report["points"] == len(points)
    assert "DetectResult(primitives=" in repr(result)
    assert repr(result.primitives[0]).startswith("DetectedPrimitive(name='p0', kind=")


def test_detect_options_reach_the_detector(plane_and_sphere):
    points, normals, truth = plane_and_sphere
    only_planes = implicitfit.detect(points, normals, kinds=["plane"])
    assert {p.kind for p in only_planes.primitives} == {"plane"}
    assert only_planes.report["kinds"] == {"plane": len(only_planes.primitives)}
    # The sphere's points are left to no primitive or to planes of a few points at most.
    big = implicitfit.detect(points, normals, min_points=2000)
    assert big.report["min_points"] == 2000
    assert all(len(p.indices) >= 2000 for p in big.primitives)
    assert implicitfit.detect(points, normals, threshold=0.01).report["threshold"] == 0.01
    with pytest.raises(ValueError, match="kinds"):
        implicitfit.detect(points, normals, kinds=["ellipse"])
    with pytest.raises(ValueError, match="seed"):
        implicitfit.detect(points, normals, seed=-1)
    with pytest.raises(ValueError, match="threshold"):
        implicitfit.detect(points, normals, threshold=0)
    with pytest.raises(TypeError):
        implicitfit.detect(points, normals, 1)  # the options are keyword-only


def test_the_same_seed_detects_the_same_primitives(plane_and_sphere):
    points, normals, _ = plane_and_sphere
    a = implicitfit.detect(points, normals, seed=7)
    b = implicitfit.detect(points, normals, seed=7)
    assert [p.model for p in a.primitives] == [p.model for p in b.primitives]
    assert np.array_equal(a.labels, b.labels)


def test_fit_inliers_are_the_points_on_the_truth_within_the_band():
    truth = model({"type": "cylinder", "point": [1, 2, 3], "axis": [0.2, -0.3, 0.9],
                   "radius": 0.6})
    noise = 0.003
    points, normals = implicitfit.sample(truth, 6000, noise=noise, outliers=0.2, seed=4)
    result = implicitfit.fit(points, normals, kind="cylinder", seed=1)
    assert isinstance(result, implicitfit.FitResult) and result.success
    inliers = result.inliers
    assert inliers.dtype == np.int64 and np.all(np.diff(inliers) > 0)
    assert len(inliers) == result.report["inliers"]
    # Every inlier is within the fit's final band (3 sigma) of the fitted surface ...
    band = 3 * result.report["sigma"]
    assert np.all(np.abs(result.model.evaluate(points[inliers])) <= band * (1 + 1e-9))
    # ... and near the truth surface; and the points near the truth are inliers.
    truth_distance = np.abs(truth.evaluate(points))
    assert np.mean(truth_distance[inliers] < 4 * noise) > 0.99
    near = np.flatnonzero(truth_distance < 2 * noise)
    assert len(np.intersect1d(near, inliers)) > 0.9 * len(near)
    # Unpacking as before: (model, report).
    fitted, report = result
    assert fitted is result.model and report is result.report
    assert result[0] is result.model and result[1] is result.report and len(result) == 2
    assert repr(result).startswith("FitResult(success=True, kind='cylinder', inliers=")


def test_a_failed_fit_has_no_model_and_no_inliers():
    # A flat patch with its normals is no sphere (the check refuses what the detector calls a
    # plane).
    points, normals = implicitfit.sample(model(PLANE), 2000, noise=NOISE, seed=1)
    result = implicitfit.fit(points, normals, kind="sphere", seed=1)
    assert not result.success, repr(result)
    assert result.model is None and len(result.inliers) == 0
    assert result.report["success"] is False and "sphere" in result.report["message"]
    assert repr(result).startswith("FitResult(success=False, inliers=0 of 2000, message=")


@pytest.mark.parametrize("kind", ["plane", "sphere", "torus"])
def test_points_filling_a_volume_fit_no_primitive(kind):
    # 400 uniform points in a cube, no normals: no surface explains them (the command line's
    # volume rule, fit/detect/checked_fit.h); a fixed threshold is still the user's to give.
    points = np.random.default_rng(3).uniform(-1, 1, (400, 3))
    result = implicitfit.fit(points, kind=kind)
    assert not result.success and result.model is None
    assert "fill a volume" in result.report["message"]
    assert len(result.inliers) == 0
    fixed = implicitfit.fit(points, kind=kind, threshold=0.05)
    assert "fill a volume" not in fixed.report["message"]


def test_mesh_of_a_sphere_lies_on_it_and_is_closed():
    sphere = {"format": "implicitfit-model", "version": 1, "root": SPHERE}
    vertices, faces = implicitfit.mesh(sphere, cell=0.05)
    assert vertices.dtype == np.float64 and vertices.shape[1] == 3
    assert faces.dtype == np.int64 and faces.shape[1] == 3
    assert faces.min() == 0 and faces.max() == len(vertices) - 1
    radii = np.linalg.norm(vertices - SPHERE["center"], axis=1)
    assert np.max(np.abs(radii - SPHERE["radius"])) < 1e-9
    # Closed: every edge in two triangles; a sphere: Euler characteristic 2.
    edges = np.sort(np.vstack([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert np.all(counts == 2)
    assert len(vertices) - len(counts) + len(faces) == 2
    # A Model gives the same mesh as its dict; a coarser cell fewer triangles.
    v2, f2 = implicitfit.mesh(model(SPHERE), cell=0.05)
    assert np.array_equal(v2, vertices) and np.array_equal(f2, faces)
    assert len(implicitfit.mesh(sphere, cell=0.2)[1]) < len(faces)
    with pytest.raises(ValueError, match="cell"):
        implicitfit.mesh(sphere, cell=-1)
    with pytest.raises(ValueError):
        implicitfit.mesh({"format": "implicitfit-model", "version": 1, "root": {"type": "blob"}})


def test_reconstruct_a_sphere_gives_a_verified_solid_on_it():
    points, normals = implicitfit.sample(model(SPHERE), 4000, noise=NOISE, seed=5)
    result = implicitfit.reconstruct(points, normals, seed=1)
    assert isinstance(result, implicitfit.ReconstructResult)
    assert result.success and result.verified, result.message
    assert result.report["verification"]["verified"] is True
    solid = implicitfit.Model.from_json(json.dumps(result.model))
    assert np.sqrt(np.mean(solid.evaluate(points) ** 2)) < 2 * NOISE
    assert solid.evaluate(np.array([SPHERE["center"]]))[0] < 0  # inside
    vertices, _ = implicitfit.mesh(result.model)
    radii = np.linalg.norm(vertices - SPHERE["center"], axis=1)
    assert np.max(np.abs(radii - SPHERE["radius"])) < 10 * NOISE
    assert "ReconstructResult(success=True, verified=True" in repr(result)


def test_reconstruct_without_a_solid_returns_no_model():
    points = np.random.default_rng(1).uniform(-1, 1, (300, 3))
    result = implicitfit.reconstruct(points)
    assert not result.success and result.model is None and result.message
    assert result.report["success"] is False


@pytest.mark.parametrize("job", ["detect", "reconstruct", "mesh"])
def test_the_gil_is_released_during_the_job(plane_and_sphere, job):
    points, normals, _ = plane_and_sphere
    call = {"detect": lambda: implicitfit.detect(points, normals),
            "reconstruct": lambda: implicitfit.reconstruct(points[3000:], normals[3000:]),
            "mesh": lambda: implicitfit.mesh(model(SPHERE), cell=0.01)}[job]
    assert spins_during(call) > 1000
