"""fit_tree, fit_patch and sample return named results (attributes, repr) that still unpack as
the tuples they used to be; the expected values come from the generating models."""
import json

import numpy as np

import implicitfit

CENTRE = np.array([0.5, -1.0, 2.0])
RADIUS = 1.5


def model(root):
    return implicitfit.Model.from_json(
        json.dumps({"format": "implicitfit-model", "version": 1, "root": root}))


def sphere(centre=CENTRE, radius=RADIUS):
    return model({"type": "sphere", "center": list(centre), "radius": radius})


def distance(points, centre=CENTRE, radius=RADIUS):
    """|x - c| - r: the signed distance to the sphere, computed here, not by the module."""
    return np.linalg.norm(points - centre, axis=1) - radius


def test_sample_returns_points_normals_and_the_truth():
    sigma, n = 0.01, 3000
    far = CENTRE + [5, 0, 0]
    two = model({"type": "union", "delta": 0.1, "epsilon": 0.05, "order": 2, "children": [
        {"type": "sphere", "center": list(CENTRE), "radius": RADIUS},
        {"type": "sphere", "center": list(far), "radius": RADIUS}]})
    result = implicitfit.sample(two, n, noise=sigma, outliers=0.1, seed=2)
    assert isinstance(result, implicitfit.SampleResult)
    points, normals = result  # unpacks as before
    assert points is result.points and normals is result.normals
    assert result[0] is result.points and result[1] is result.normals and len(result) == 2
    assert points.shape == (n, 3) and normals.shape == (n, 3)
    # round(0.1 n) uniform outliers, labelled -1; every other point is on the sphere its label
    # names, within 6 sigma (Gaussian noise along the normal: P(|Z| > 6) = 2e-9 per point).
    assert result.outliers.dtype == np.bool_ and result.outliers.sum() == round(0.1 * n)
    assert result.labels.dtype == np.int64
    assert np.all(result.labels[result.outliers] == -1)
    inliers = ~result.outliers
    d0, d1 = distance(points, CENTRE), distance(points, far)
    on = np.where(result.labels == 0, d0, d1)[inliers]
    assert set(result.labels[inliers].tolist()) == {0, 1}
    assert np.all(np.abs(on) <= 6 * sigma)
    assert abs(np.sqrt(np.mean(on ** 2)) - sigma) < 0.1 * sigma
    assert result.truth_kinds == ["sphere", "sphere"]
    assert result.report["points"] == n and result.report["outliers"] == round(0.1 * n)
    assert result.report["job"] == "sample" and result.report["settings"]["seed"] == 2
    assert repr(result) == "SampleResult(points=3000, outliers=300, truth_kinds=['sphere', 'sphere'])"


def test_sample_is_the_same_as_before_for_the_same_seed():
    a = implicitfit.sample(sphere(), 500, noise=0.01, seed=4)
    b = implicitfit.sample(sphere(), 500, noise=0.01, seed=4)
    np.testing.assert_array_equal(a.points, b.points)
    assert not a.outliers.any() and np.all(a.labels == 0)


def test_fit_tree_returns_a_fit_result_with_its_inliers():
    sigma = 0.002
    points, normals = implicitfit.sample(sphere(), 2000, noise=sigma, seed=3)
    init = sphere(CENTRE + [0.1, -0.05, 0.05], 1.3)
    result = implicitfit.fit_tree(points, normals, init)
    assert isinstance(result, implicitfit.FitResult) and result.success, repr(result)
    fitted, report = result
    assert fitted is result.model and report is result.report
    p = fitted.parameters
    assert np.linalg.norm(np.asarray(p["center"]) - CENTRE) < 5 * sigma
    assert abs(p["radius"] - RADIUS) < 5 * sigma
    # The inliers: the points within 3 sigma (the fit's) of the fitted sphere, ascending.
    inliers = result.inliers
    assert inliers.dtype == np.int64 and np.all(np.diff(inliers) > 0)
    assert len(inliers) == report["inliers"]
    band = 3 * report["sigma"]
    assert np.all(np.abs(distance(points[inliers], np.asarray(p["center"]), p["radius"]))
                  <= band * (1 + 1e-9))
    # Gaussian noise: about 99.7% of the points are within 3 sigma.
    assert len(inliers) > 0.98 * len(points)
    assert repr(result).startswith("FitResult(success=True, kind='sphere', inliers=")


def test_fit_patch_returns_a_fit_result_of_every_point():
    points, normals = implicitfit.sample(sphere(), 1500, seed=5)
    cap = points[:, 2] > CENTRE[2] + 0.5  # a cap of the sphere
    result = implicitfit.fit_patch(points[cap], normals[cap], degree=2)
    assert isinstance(result, implicitfit.FitResult) and result.success, repr(result)
    np.testing.assert_array_equal(result.inliers, np.arange(cap.sum()))
    # A quadric patch holds the sphere exactly: the cap's points are on its zero set.
    assert result.report["rms_distance"] < 1e-6
    model_, report = result
    assert model_.kind == "bernstein_patch" and report["points"] == cap.sum()
    assert repr(result).startswith("FitResult(success=True, kind='bernstein_patch', inliers=")
