"""Round trips and closed forms: models through JSON and files, arrays in and out, evaluation
against formulas computed here with NumPy, certificates against hand-derived Guo matrices."""
import json

import numpy as np
import pytest

import implicitfit
from conftest import write_model

CYLINDER = {"type": "cylinder", "point": [0.5, -1.0, 2.0], "axis": [0.0, 0.6, 0.8], "radius": 0.75}
TORUS = {"type": "torus", "center": [1.0, 2.0, 3.0], "axis": [0.0, 0.0, 1.0],
         "major_radius": 2.0, "minor_radius": 0.5}
BLEND = {"type": "union", "delta": 0.3, "epsilon": 0.2, "order": 2, "children": [
    {"type": "sphere", "center": [0, 0, 0], "radius": 1},
    {"type": "sphere", "center": [1.6, 0, 0], "radius": 0.8, "name": "cap"}]}


def model_text(root):
    return json.dumps({"format": "implicitfit-model", "version": 1, "root": root})


def test_json_round_trip_keeps_every_parameter_bit_for_bit():
    for root in (CYLINDER, TORUS, BLEND):
        m = implicitfit.Model.from_json(model_text(root))
        again = implicitfit.Model.from_json(m.to_json())
        assert again.to_json() == m.to_json()
        assert json.loads(m.to_json())["root"]["type"] == root["type"]


def test_save_load_round_trip_and_file_content(tmp_path):
    m = implicitfit.Model.from_json(model_text(BLEND))
    m.save(tmp_path / "m.json")
    assert (tmp_path / "m.json").read_text() == m.to_json() + "\n"
    assert implicitfit.Model.load(str(tmp_path / "m.json")).to_json() == m.to_json()


def test_parameters_by_field():
    p = implicitfit.Model.from_json(model_text(CYLINDER)).parameters
    assert set(p) == {"point", "axis", "radius"}
    np.testing.assert_array_equal(p["point"], CYLINDER["point"])
    np.testing.assert_array_equal(p["axis"], CYLINDER["axis"])
    assert p["radius"] == CYLINDER["radius"]
    blend = implicitfit.Model.from_json(model_text(BLEND)).parameters
    assert blend["delta"] == 0.3 and blend["epsilon"] == 0.2
    assert blend["children[0].radius"] == 1.0 and blend["cap.radius"] == 0.8
    np.testing.assert_array_equal(blend["cap.center"], [1.6, 0, 0])


def test_repr_and_kind():
    m = implicitfit.Model.from_json(model_text(CYLINDER))
    assert m.kind == "cylinder"
    assert repr(m).startswith("implicitfit.Model({") and '"radius":0.75' in repr(m)


def test_evaluate_and_gradient_against_closed_forms():
    rng = np.random.default_rng(1)
    x = rng.uniform(-3, 3, size=(500, 3))
    cyl = implicitfit.Model.from_json(model_text(CYLINDER))
    a = np.array(CYLINDER["axis"]) / np.linalg.norm(CYLINDER["axis"])
    d = x - CYLINDER["point"]
    radial = d - np.outer(d @ a, a)
    rho = np.linalg.norm(radial, axis=1)
    np.testing.assert_allclose(cyl.evaluate(x), rho - CYLINDER["radius"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(cyl.gradient(x), radial / rho[:, None], rtol=0, atol=1e-12)

    torus = implicitfit.Model.from_json(model_text(TORUS))
    c = x - TORUS["center"]
    ring = np.hypot(np.hypot(c[:, 0], c[:, 1]) - 2.0, c[:, 2])
    np.testing.assert_allclose(torus.evaluate(x), ring - 0.5, rtol=0, atol=1e-12)


def test_gradient_of_a_blend_against_central_differences():
    m = implicitfit.Model.from_json(model_text(BLEND))
    x = np.random.default_rng(2).uniform(-1.5, 2.5, size=(200, 3))
    h = 1e-6
    numeric = np.stack([(m.evaluate(x + h * e) - m.evaluate(x - h * e)) / (2 * h) for e in np.eye(3)],
                       axis=1)
    np.testing.assert_allclose(m.gradient(x), numeric, rtol=0, atol=1e-6)


def test_float32_and_strided_inputs_are_converted_exactly():
    m = implicitfit.Model.from_json(model_text(TORUS))
    x32 = np.random.default_rng(3).uniform(-3, 3, size=(100, 3)).astype(np.float32)
    np.testing.assert_array_equal(m.evaluate(x32), m.evaluate(x32.astype(np.float64)))
    wide = np.random.default_rng(4).uniform(-3, 3, size=(100, 6))
    strided = wide[:, ::2]  # not C-contiguous
    assert not strided.flags.c_contiguous
    np.testing.assert_array_equal(m.evaluate(strided), m.evaluate(np.ascontiguousarray(strided)))
    np.testing.assert_array_equal(m.evaluate(strided.tolist()),
                                  m.evaluate(np.ascontiguousarray(strided)))


def test_read_cloud_matches_the_text_file(data_dir):
    points, normals = implicitfit.read_cloud(str(data_dir / "cgal_sphere_single.xyz"))
    text = np.loadtxt(data_dir / "cgal_sphere_single.xyz")
    assert points.shape == (422, 3) and points.dtype == np.float64
    np.testing.assert_array_equal(points, text[:, :3])
    expected = text[:, 3:] / np.linalg.norm(text[:, 3:], axis=1)[:, None]
    np.testing.assert_allclose(normals, expected, rtol=0, atol=1e-15)
    # The arrays own no copy: they wrap the library's vectors.
    assert not points.flags.owndata and points.base is not None


def test_read_cloud_without_normals(tmp_path, data_dir):
    xyz = np.loadtxt(data_dir / "cgal_sphere_single.xyz")[:, :3]
    np.savetxt(tmp_path / "bare.xyz", xyz, fmt="%.17g")
    points, normals = implicitfit.read_cloud(str(tmp_path / "bare.xyz"))
    assert normals is None
    _, estimated = implicitfit.read_cloud(str(tmp_path / "bare.xyz"), estimate=True)
    # A sphere about its centre: estimated normals point outward (MST orientation).
    centre = points.mean(axis=0)
    radial = (points - centre) / np.linalg.norm(points - centre, axis=1)[:, None]
    assert np.mean(np.einsum("ij,ij->i", estimated, radial)) > 0.95


def test_estimate_normals_on_a_plane_toward_a_viewpoint():
    rng = np.random.default_rng(5)
    xy = rng.uniform(-1, 1, size=(2000, 2))
    points = np.column_stack([xy, 0.3 * xy[:, 0] - 0.2 * xy[:, 1] + 1.0])
    truth = np.array([-0.3, 0.2, 1.0]) / np.linalg.norm([-0.3, 0.2, 1.0])
    normals = implicitfit.estimate_normals(points, viewpoint=[0, 0, 10])
    np.testing.assert_allclose(normals, np.tile(truth, (2000, 1)), atol=1e-9)
    normals = implicitfit.estimate_normals(points, viewpoint=[0, 0, -10])
    np.testing.assert_allclose(normals, np.tile(-truth, (2000, 1)), atol=1e-9)


def test_sample_lies_on_the_zero_set_with_gradient_normals():
    m = implicitfit.Model.from_json(model_text(TORUS))
    points, normals = implicitfit.sample(m, 3000, seed=7)
    assert points.shape == (3000, 3) and normals.shape == (3000, 3)
    assert np.max(np.abs(m.evaluate(points))) < 1e-9
    g = m.gradient(points)
    np.testing.assert_allclose(normals, g / np.linalg.norm(g, axis=1)[:, None], atol=1e-9)
    again, _ = implicitfit.sample(m, 3000, seed=7)
    np.testing.assert_array_equal(points, again)
    noisy, _ = implicitfit.sample(m, 20000, noise=0.01, seed=7)
    assert np.std(m.evaluate(noisy)) == pytest.approx(0.01, rel=0.05)


def degree2_patch(control_points):
    return model_text({"type": "bernstein_patch", "degree": 2,
                       "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                       "control_points": control_points})


def test_check_against_hand_derived_guo_matrices():
    # docs/design.md order for k = 2: 2000, 1100, 1010, 1001, 0200, 0110, 0101, 0020, 0011, 0002.
    # b(2e_i) = 1 for i = 1..3, all else 0: A_ij = b(e_i + e_j) + b(2e_4) - b(e_i+e_4) - b(e_j+e_4) = I.
    convex = implicitfit.Model.from_json(degree2_patch([1, 0, 0, 0, 1, 0, 0, 1, 0, 0]))
    report = implicitfit.check(convex)
    assert report["convex"] is True
    assert len(report["patches"]) == 1
    assert {k: report["patches"][0][k] for k in ("degree", "convex", "min_eigenvalue")} == {
        "degree": 2, "convex": True, "min_eigenvalue": 1.0}
    # b(2e_1) = 1 only: A = diag(1, 0, 0), smallest eigenvalue 0: not certified.
    flat = implicitfit.check(implicitfit.Model.from_json(degree2_patch([1, 0, 0, 0, 0, 0, 0, 0, 0, 0])))
    assert flat["convex"] is False
    assert flat["patches"][0]["min_eigenvalue"] == pytest.approx(0.0, abs=1e-15)
    no_patch = implicitfit.Model.from_json(model_text(CYLINDER))
    # No patch: judged by the tree certificate (a cylinder's distance is a convex function).
    report = implicitfit.check(no_patch)
    assert report["convex"] is True and report["patches"] == []
    assert report["tree"]["certified"] is True
