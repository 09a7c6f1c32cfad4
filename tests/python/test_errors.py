"""Bad input: ValueError for wrong shapes, NaN, too few points and invalid options; OSError with
exactly the command line's message (after its "implicitfit <command>: " prefix) for files."""
import re

import numpy as np
import pytest

import implicitfit
from conftest import run

SPHERE = ('{"format": "implicitfit-model", "version": 1, '
          '"root": {"type": "sphere", "center": [0, 0, 0], "radius": 1}}')


@pytest.fixture(scope="module")
def cloud():
    return implicitfit.sample(implicitfit.Model.from_json(SPHERE), 500, seed=1)


@pytest.mark.parametrize("bad, shape", [(np.zeros((10, 2)), "(10, 2)"), (np.zeros(3), "(3,)"),
                                        (np.zeros((4, 3, 1)), "(4, 3, 1)")])
def test_wrong_shapes(bad, shape):
    message = r"points: expected an \(N, 3\) array, got shape " + re.escape(shape)
    with pytest.raises(ValueError, match=message):
        implicitfit.fit(bad)
    with pytest.raises(ValueError, match="expected an"):
        implicitfit.Model.from_json(SPHERE).evaluate(bad)


def test_not_numbers():
    with pytest.raises(ValueError, match="points: not convertible"):
        implicitfit.fit([["a", "b", "c"]] * 30)


def test_nan_and_infinity_name_the_row(cloud):
    points, normals = cloud
    bad = points.copy()
    bad[123, 1] = np.nan
    with pytest.raises(ValueError, match=r"points\[123\]: not a finite number"):
        implicitfit.fit(bad, normals)
    bad_normals = normals.copy()
    bad_normals[7] = [np.inf, 0, 0]
    with pytest.raises(ValueError, match=r"normals\[7\]: not a finite number"):
        implicitfit.fit(points, bad_normals)
    bad_normals[7] = 0
    with pytest.raises(ValueError, match=r"normals\[7\]: zero vector"):
        implicitfit.fit(points, bad_normals)


def test_too_few_points_and_mismatched_normals(cloud):
    points, normals = cloud
    with pytest.raises(ValueError, match="points: 5 points, at least 20 are needed"):
        implicitfit.fit(points[:5], normals[:5])
    with pytest.raises(ValueError, match="points: 2 points, at least 3 are needed"):
        implicitfit.estimate_normals(points[:2])
    with pytest.raises(ValueError, match="points: 9 points, at least 10 are needed"):
        implicitfit.fit_patch(points[:9], normals[:9])
    with pytest.raises(ValueError, match="normals: 499 rows for 500 points"):
        implicitfit.fit(points, normals[:-1])


def test_invalid_options(cloud):
    points, normals = cloud
    with pytest.raises(ValueError, match="kind ellipse: unknown"):
        implicitfit.fit(points, normals, kind="ellipse")
    with pytest.raises(ValueError, match="threshold"):
        implicitfit.fit(points, normals, threshold=-1)
    with pytest.raises(ValueError, match="seed"):
        implicitfit.fit(points, normals, seed=-1)
    with pytest.raises(ValueError, match=r"fix\[radius\]: expected a number"):
        implicitfit.fit(points, normals, kind="sphere", fix={"radius": "big"})
    with pytest.raises(ValueError, match="colour"):
        implicitfit.fit(points, normals, kind="sphere", fix={"colour": 1})
    with pytest.raises(ValueError):
        implicitfit.fit_patch(points, normals, degree=7)
    # The patch mesh's options, checked before any work as on the command line (exit 2 there).
    with pytest.raises(ValueError, match="degree"):
        implicitfit.fit_patch_mesh(points, normals, degree=7)
    with pytest.raises(ValueError, match="continuity"):
        implicitfit.fit_patch_mesh(points, normals, continuity=2)
    with pytest.raises(ValueError, match="convex"):
        implicitfit.fit_patch_mesh(points, normals, convex=True, levels=2)
    with pytest.raises(ValueError, match="levels: must be >= 0"):
        implicitfit.fit_patch_mesh(points, normals, continuity=0, levels=-1)
    with pytest.raises(ValueError, match="count"):
        implicitfit.sample(implicitfit.Model.from_json(SPHERE), 0)
    with pytest.raises(ValueError, match="outliers"):
        implicitfit.sample(implicitfit.Model.from_json(SPHERE), 10, outliers=1.0)


def test_invalid_model_json_names_the_field():
    with pytest.raises(ValueError, match="root.radius"):
        implicitfit.Model.from_json(SPHERE.replace('"radius": 1', '"radius": -1'))
    with pytest.raises(ValueError, match="invalid JSON"):
        implicitfit.Model.from_json("{not json")


def test_failed_fit_returns_no_model_and_says_why(cloud):
    points, normals = cloud
    model, report = implicitfit.fit(points, normals, kind="sphere", fix={"radius": 0.01})
    assert model is None and report["success"] is False and report["message"]


def cli_message(cli, *args):
    code, _, err = run(cli, *args)
    assert code == 2
    prefix = f"implicitfit {args[0]}: "
    assert err.startswith(prefix)
    return err[len(prefix):].rstrip("\n")


def test_io_errors_carry_the_command_lines_messages(cli, tmp_path):
    missing = str(tmp_path / "missing.xyz")
    expected = cli_message(cli, "fit", missing, "--model", "sphere", "--out", tmp_path / "o.json")
    with pytest.raises(OSError) as e:
        implicitfit.read_cloud(missing)
    assert str(e.value) == expected

    malformed = tmp_path / "malformed.xyz"
    malformed.write_text("0 0 0 0 0 1\n1 2\n")
    expected = cli_message(cli, "fit", malformed, "--model", "sphere", "--out", tmp_path / "o.json")
    with pytest.raises(OSError) as e:
        implicitfit.read_cloud(malformed)
    assert str(e.value) == expected and ":2:" in expected

    bad_model = tmp_path / "bad.json"
    bad_model.write_text(SPHERE.replace('"radius": 1', '"radius": 0'))
    expected = cli_message(cli, "check", bad_model)
    with pytest.raises(OSError) as e:
        implicitfit.Model.load(str(bad_model))
    assert str(e.value) == expected

    with pytest.raises(OSError, match="no_such_dir"):
        implicitfit.Model.from_json(SPHERE).save(str(tmp_path / "no_such_dir" / "m.json"))
    assert not (tmp_path / "no_such_dir").exists()
