"""The module and the command line on the same files: bit-identical models for the same seed,
the same reports (but the timing, where the normals came from and the command line's header),
the same certificates and values, the same detected primitives and reconstructed solids. Both
run the same library code (fit/common/fit_report.h, model/certificates/convexity_report.h,
jobs/)."""
import json

import numpy as np
import pytest

import implicitfit
from conftest import run, write_model

# Report fields that legitimately differ: wall time, and "normals" ("read from file" on the
# command line, "given" when the arrays come from Python).
# The timing, where the normals came from, and the command line's report header
# (apps/report_header.h: format, job, input, settings, ...), which the module's reports leave out.
VOLATILE = {"seconds", "normals", "format", "format_version", "job", "tool_version", "input",
            "settings", "seed", "units"}


def cli_fit(cli, tmp_path, cloud, *options):
    out, report = tmp_path / "cli.json", tmp_path / "cli_report.json"
    code, _, err = run(cli, "fit", cloud, "--out", out, "--report", report, *options)
    assert code == 0, err
    return out.read_text(), json.loads(report.read_text())


def assert_same_fit(cli_result, py_result):
    cli_text, cli_report = cli_result
    model, report = py_result
    assert model is not None, report["message"]
    assert model.to_json() + "\n" == cli_text  # every parameter bit for bit (round-trip precision)
    assert {k: v for k, v in report.items() if k not in VOLATILE} == \
           {k: v for k, v in cli_report.items() if k not in VOLATILE}


@pytest.fixture(scope="module")
def noisy_cylinder(tmp_path_factory, cli):
    d = tmp_path_factory.mktemp("cylinder")
    truth = write_model(d / "truth.json", {"type": "cylinder", "point": [1, 2, 3],
                                           "axis": [0.2, -0.3, 0.9], "radius": 0.6})
    code, _, err = run(cli, "sample", truth, "--count", "6000", "--noise", "0.004", "--outliers", "0.15",
                       "--seed", "11", "--out", d / "cloud.xyz")
    assert code == 0, err
    return d / "cloud.xyz"


@pytest.mark.parametrize("seed", [0, 3])
def test_cylinder_fit_is_bit_identical_to_the_command_line(cli, tmp_path, noisy_cylinder, seed):
    expected = cli_fit(cli, tmp_path, noisy_cylinder, "--model", "cylinder", "--seed", seed)
    points, normals = implicitfit.read_cloud(str(noisy_cylinder))
    assert_same_fit(expected, implicitfit.fit(points, normals, kind="cylinder", seed=seed))


def test_options_reach_the_fitter_as_on_the_command_line(cli, tmp_path, noisy_cylinder):
    expected = cli_fit(cli, tmp_path, noisy_cylinder, "--model", "cylinder", "--seed", "5",
                       "--threshold", "0.05", "--fix", "radius=0.6")
    points, normals = implicitfit.read_cloud(str(noisy_cylinder))
    result = implicitfit.fit(points, normals, kind="cylinder", seed=5, threshold=0.05,
                             fix={"radius": np.float64(0.6)})
    assert_same_fit(expected, result)
    assert result[0].parameters["radius"] == 0.6


def test_sphere_on_a_binary_ply_scan(cli, tmp_path, data_dir):
    cloud = data_dir / "cgal_spheres_10.ply"
    expected = cli_fit(cli, tmp_path, cloud, "--model", "sphere", "--seed", "2")
    points, normals = implicitfit.read_cloud(str(cloud))
    assert_same_fit(expected, implicitfit.fit(points, normals, kind="sphere", seed=2))


def test_normals_estimated_as_on_the_command_line(cli, tmp_path, data_dir):
    # No normals in the file: the command line estimates them (MST); fit(points) must too.
    bare = tmp_path / "bare.xyz"
    np.savetxt(bare, np.loadtxt(data_dir / "cgal_sphere_single.xyz")[:, :3], fmt="%.17g")
    cli_text, cli_report = cli_fit(cli, tmp_path, bare, "--model", "sphere", "--seed", "1")
    points, normals = implicitfit.read_cloud(str(bare))
    assert normals is None
    model, report = implicitfit.fit(points, kind="sphere", seed=1)
    assert model.to_json() + "\n" == cli_text
    assert report["normals"] == cli_report["normals"]


def test_viewpoint_normals_of_a_pcd_scan(cli, tmp_path, data_dir):
    # The PCD's VIEWPOINT orients the estimated normals: read_cloud(estimate=True) does the same.
    cloud = data_dir / "pcl_milk_carton_kinect.pcd"
    expected = cli_fit(cli, tmp_path, cloud, "--model", "plane", "--seed", "4")
    points, normals = implicitfit.read_cloud(str(cloud), estimate=True)
    assert_same_fit(expected, implicitfit.fit(points, normals, kind="plane", seed=4))


def test_patch_and_tree_fits(cli, tmp_path, noisy_cylinder, data_dir):
    cloud = data_dir / "cgal_sphere_single.xyz"
    points, normals = implicitfit.read_cloud(str(cloud))
    expected = cli_fit(cli, tmp_path, cloud, "--model", "quadric-patch", "--convex")
    assert_same_fit(expected, implicitfit.fit_patch(points, normals, degree=2, convex=True))
    expected = cli_fit(cli, tmp_path, cloud, "--model", "cubic-patch")
    assert_same_fit(expected, implicitfit.fit(points, normals, kind="cubic-patch"))

    init = write_model(tmp_path / "init.json",
                       {"type": "sphere", "center": [0.5, -0.2, -0.7], "radius": 0.3})
    expected = cli_fit(cli, tmp_path, cloud, "--init", init)
    assert_same_fit(expected, implicitfit.fit_tree(points, normals, implicitfit.Model.load(str(init))))


def test_refined_patch_mesh_matches_the_command_line(cli, tmp_path):
    # A box (sharp edges): C0 with one level of refinement at the creases, bit for bit as
    # `fit --model patch-mesh --cells 5 --continuity 0 --levels 1`, with the same refinement report.
    truth = write_model(tmp_path / "box.json", {"type": "box", "center": [0.1, 0, -0.1],
                                                "axes": [[1, 0, 0], [0, 1, 0]],
                                                "half_sizes": [0.6, 0.4, 0.3]})
    cloud = tmp_path / "box.xyz"
    code, _, err = run(cli, "sample", truth, "--count", "2000", "--noise", "0.001", "--seed", "4",
                       "--out", cloud)
    assert code == 0, err
    expected = cli_fit(cli, tmp_path, cloud, "--model", "patch-mesh", "--cells", "5",
                       "--continuity", "0", "--levels", "1")
    points, normals = implicitfit.read_cloud(str(cloud))
    result = implicitfit.fit_patch_mesh(points, normals, cells=5, continuity=0, levels=1)
    assert_same_fit(expected, result)
    assert result.report["refinement"]["levels"] == 1
    assert len(result.inliers) == len(points)


def test_sample_matches_the_command_line(cli, tmp_path):
    truth = write_model(tmp_path / "torus.json", {"type": "torus", "center": [0, 0, 1], "axis": [1, 0, 0],
                                                  "major_radius": 1.5, "minor_radius": 0.4})
    code, _, err = run(cli, "sample", truth, "--count", "2000", "--noise", "0.01", "--outliers", "0.1",
                       "--seed", "9", "--out", tmp_path / "cli.xyz")
    assert code == 0, err
    text = np.loadtxt(tmp_path / "cli.xyz")
    points, normals = implicitfit.sample(implicitfit.Model.load(str(truth)), 2000, noise=0.01,
                                         outliers=0.1, seed=9)
    np.testing.assert_array_equal(points, text[:, :3])   # written with %.17g: exact
    np.testing.assert_array_equal(normals, text[:, 3:])


def test_eval_matches_the_command_line(cli, noisy_cylinder):
    model_text = '{"format": "implicitfit-model", "version": 1, "root": {"type": "cone", "apex": [1, 2, 3], ' \
                 '"axis": [0, 0, 1], "half_angle": 0.4}}'
    path = noisy_cylinder.parent / "cone.json"
    path.write_text(model_text)
    code, out, err = run(cli, "eval", path, noisy_cylinder)
    assert code == 0, err
    points, _ = implicitfit.read_cloud(str(noisy_cylinder))
    np.testing.assert_array_equal(implicitfit.Model.from_json(model_text).evaluate(points),
                                  np.array(out.split(), dtype=float))


def test_check_matches_check_json(cli, tmp_path):
    patch = {"type": "bernstein_patch", "degree": 3,
             "vertices": [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2]],
             "control_points": [float(v) for v in np.random.default_rng(6).normal(size=20)]}
    files = [write_model(tmp_path / "random.json", patch),
             write_model(tmp_path / "blend.json", {"type": "union", "delta": 0.2, "epsilon": 0.1, "order": 2,
                                                   "children": [patch, {"type": "sphere", "center": [0, 0, 0],
                                                                        "radius": 1}]})]
    code, out, _ = run(cli, "check", "--json", *files)
    assert code in (0, 1)
    for entry, path in zip(json.loads(out)["files"], files):
        assert entry.pop("file") == str(path)
        assert implicitfit.check(implicitfit.Model.load(str(path))) == entry


def test_detect_finds_what_the_command_line_finds(cli, tmp_path):
    """implicitfit.detect on read_cloud's arrays and `implicitfit detect` on the file (both seed
    1): the same primitives (the scene file's model nodes), the same labels, the same report but
    the header, the timing and the cloud's name."""
    sphere = implicitfit.Model.from_json(json.dumps({"format": "implicitfit-model", "version": 1,
        "root": {"type": "sphere", "center": [3, 0, 1.5], "radius": 1}}))
    plane = implicitfit.Model.from_json(json.dumps({"format": "implicitfit-model", "version": 1,
        "root": {"type": "plane", "normal": [0, 0, 1], "offset": 0}}))
    p1, n1 = implicitfit.sample(plane, 2500, noise=0.002, seed=1)
    p2, n2 = implicitfit.sample(sphere, 2500, noise=0.002, seed=2)
    cloud = tmp_path / "cloud.xyz"
    np.savetxt(cloud, np.hstack([np.vstack([p1, p2]), np.vstack([n1, n2])]), fmt="%.17g")
    scene, labels, report = tmp_path / "scene.json", tmp_path / "labels.txt", tmp_path / "r.json"
    code, _, err = run(cli, "detect", cloud, "--out", scene, "--labels", labels, "--report", report,
                       "--seed", "1", "--quiet")
    assert code == 0, err
    points, normals = implicitfit.read_cloud(str(cloud))
    result = implicitfit.detect(points, normals, seed=1)
    cli_scene = json.loads(scene.read_text())
    assert len(result.primitives) == len(cli_scene["primitives"]) >= 2
    for p, c in zip(result.primitives, cli_scene["primitives"]):
        assert (p.name, p.model, len(p.indices), p.rms_distance, p.normal_side) == \
               (c["name"], c["model"], c["points"], c["rms_distance"], c["normal_side"])
    assert np.array_equal(result.labels, np.loadtxt(labels, dtype=np.int64))
    volatile = VOLATILE | {"cloud"}
    assert {k: v for k, v in result.report.items() if k not in volatile} == \
           {k: v for k, v in json.loads(report.read_text()).items() if k not in volatile}


def test_reconstruct_builds_what_the_command_line_builds(cli, tmp_path):
    """implicitfit.reconstruct on read_cloud's arrays and `implicitfit reconstruct` on the file
    (both seed 1): the same model file, the same verdict."""
    sphere = implicitfit.Model.from_json(json.dumps({"format": "implicitfit-model", "version": 1,
        "root": {"type": "sphere", "center": [3, 0, 1.5], "radius": 1}}))
    p, n = implicitfit.sample(sphere, 3000, noise=0.002, seed=3)
    cloud = tmp_path / "cloud.xyz"
    np.savetxt(cloud, np.hstack([p, n]), fmt="%.17g")
    out, report = tmp_path / "solid.json", tmp_path / "r.json"
    code, _, err = run(cli, "reconstruct", cloud, "--out", out, "--report", report, "--seed", "1",
                       "--quiet")
    assert code == 0, err
    points, normals = implicitfit.read_cloud(str(cloud))
    result = implicitfit.reconstruct(points, normals, seed=1)
    assert result.success and result.model == json.loads(out.read_text())
    cli_report = json.loads(report.read_text())
    for key in ("success", "expression", "bounded", "rms_distance", "inliers", "model_written",
                "primitives", "blends", "closures", "separators"):
        assert result.report[key] == cli_report[key], key
    assert result.report["verification"]["verified"] == cli_report["verification"]["verified"]
