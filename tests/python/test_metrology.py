"""The metrology estimators through the module: implicitfit.fit(..., estimator=...) on a few
probed points without normals gives the model and report `implicitfit fit --estimator` gives for
the same file (bit-identical parameters, same report but timing and the normals' origin), and the
report names the estimator."""
import json

import numpy as np
import pytest

import implicitfit
from conftest import run

# The timing, where the normals came from, and the command line's report header
# (apps/report_header.h: format, job, input, settings, ...), which the module's reports leave out.
VOLATILE = {"seconds", "normals", "format", "format_version", "job", "tool_version", "input",
            "settings", "seed", "units"}


def cmm_cylinder(path, count=14, seed=4):
    """count points on three partial circles of a cylinder of radius 5 mm, lobed form error of
    1 um, 0.1 um noise; x y z only (no normals), as a coordinate-measuring machine probes."""
    rng = np.random.default_rng(seed)
    axis = np.array([0.3, -0.2, 0.93])
    axis /= np.linalg.norm(axis)
    e1 = np.cross(axis, [1.0, 0, 0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    rows = []
    for i in range(count):
        phi = 0.2 + 3.5 * i / count
        z = -4 + 4 * (i % 3)
        r = 5 + 1e-3 * np.cos(3 * phi) + 1e-4 * rng.standard_normal()
        rows.append(np.array([120, -80, 40]) + z * axis + r * (np.cos(phi) * e1 + np.sin(phi) * e2))
    np.savetxt(path, np.array(rows), fmt="%.17g")
    return path


@pytest.mark.parametrize("estimator", ["least-squares", "minimum-zone"])
def test_estimator_reaches_the_fit_as_on_the_command_line(cli, tmp_path, estimator):
    cloud = cmm_cylinder(tmp_path / "bore.xyz")
    out, report_path = tmp_path / "cli.json", tmp_path / "cli_report.json"
    code, _, err = run(cli, "fit", cloud, "--model", "cylinder", "--estimator", estimator,
                       "--out", out, "--report", report_path)
    assert code == 0, err
    cli_report = json.loads(report_path.read_text())
    points, normals = implicitfit.read_cloud(str(cloud))
    assert normals is None
    # The command line's default seed is 1.
    model, report = implicitfit.fit(points, normals, kind="cylinder", seed=1, estimator=estimator)
    assert model is not None, report["message"]
    assert report["estimator"] == estimator == cli_report["estimator"]
    assert model.to_json() + "\n" == out.read_text()
    assert {k: v for k, v in report.items() if k not in VOLATILE} == \
           {k: v for k, v in cli_report.items() if k not in VOLATILE}
    assert report["points_only"]
    if estimator == "minimum-zone":
        assert report["zone"]["optimality_verified"]


def test_estimators_differ_and_default_is_robust(tmp_path):
    points, _ = implicitfit.read_cloud(str(cmm_cylinder(tmp_path / "bore.xyz")))
    _, robust = implicitfit.fit(points, None, kind="cylinder")
    _, ls = implicitfit.fit(points, None, kind="cylinder", estimator="least-squares")
    _, mz = implicitfit.fit(points, None, kind="cylinder", estimator="minimum-zone")
    assert robust["estimator"] == "robust"
    # The minimum zone is never wider than the least-squares form error (ISO 1101).
    assert mz["zone"]["width"] <= ls["form"]["form_error"] + 1e-15


def test_unknown_estimator_is_refused(tmp_path):
    points, _ = implicitfit.read_cloud(str(cmm_cylinder(tmp_path / "bore.xyz")))
    with pytest.raises(ValueError, match="estimator chebyshev: unknown"):
        implicitfit.fit(points, None, kind="cylinder", estimator="chebyshev")
    with pytest.raises(ValueError, match="estimator least-squares: applies to"):
        implicitfit.fit(points, None, kind="quadric-patch", estimator="least-squares")
