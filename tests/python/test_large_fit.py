"""A fit of 10^5 points: accuracy against the known truth of a sampled cylinder, and the GIL
released while the fit runs (another Python thread keeps running)."""
import numpy as np

import implicitfit
from conftest import spins_during

TRUTH_POINT = np.array([10.0, -4.0, 2.5])
TRUTH_AXIS = np.array([0.3, 0.4, 0.866])
TRUTH_AXIS /= np.linalg.norm(TRUTH_AXIS)
RADIUS, NOISE = 1.25, 0.005
CYLINDER = ('{"format": "implicitfit-model", "version": 1, "root": {"type": "cylinder", '
            f'"point": {TRUTH_POINT.tolist()}, "axis": {TRUTH_AXIS.tolist()}, "radius": {RADIUS}}}}}')


def cloud():
    truth = implicitfit.Model.from_json(CYLINDER)
    return truth, implicitfit.sample(truth, 100_000, noise=NOISE, outliers=0.1, seed=3)


def test_cylinder_from_100000_points():
    truth, (points, normals) = cloud()
    model, report = implicitfit.fit(points, normals, kind="cylinder", seed=1)
    assert model is not None, report["message"]
    assert report["points"] == 100_000
    p = model.parameters
    sd = report["standard_deviations"]
    # Radius within 5 standard deviations (plus a floor for the sampler's box edge effects).
    assert abs(p["radius"] - RADIUS) < 5 * sd["radius"] + 1e-4
    angle = np.degrees(np.arccos(min(1.0, abs(p["axis"] @ TRUTH_AXIS))))
    assert angle < 0.05
    # The fitted axis line passes the truth's: distance of the truth point to it.
    d = TRUTH_POINT - p["point"]
    assert np.linalg.norm(d - (d @ p["axis"]) * p["axis"]) < 1e-3
    # About 90% inliers (10% outliers), noise recovered by the robust scale.
    assert 0.88 * 100_000 < report["inliers"] < 0.92 * 100_000
    assert abs(report["sigma"] - NOISE) < 0.1 * NOISE
    # The residuals of the true surface's points against the fit: the noise level.
    inliers = np.abs(truth.evaluate(points)) < 4 * NOISE
    assert np.sqrt(np.mean(model.evaluate(points[inliers]) ** 2)) < 1.1 * NOISE


def test_the_gil_is_released_during_the_fit():
    _, (points, normals) = cloud()
    assert spins_during(lambda: implicitfit.fit(points, normals, kind="cylinder", seed=1)) > 1000
