#!/usr/bin/python3
"""implicitfit.fit from Python against (1) the C++ library on the same 10^5-point cloud
(bench/fit_timing: FitPrimitive in process), giving the Python overhead, and (2) a NumPy RANSAC
in the style of pyRANSAC-3D (random minimal samples, inlier count with a fixed threshold, no
refinement, no normals), written here because pyRANSAC-3D is not packaged by Debian.

  PYTHONPATH=build/python /usr/bin/python3 bench/python_comparison.py \
      --fit-timing build/bench/fit_timing [--repeats 5] [--blocks 3] [--ransac-iterations 1000]

The Python and C++ timings alternate in blocks so that load changes on a shared machine hit both.
"""
import argparse
import json
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import implicitfit

NOISE = 0.005


def model_text(root):
    return json.dumps({"format": "implicitfit-model", "version": 1, "root": root})


CYLINDER = {"type": "cylinder", "point": [10.0, -4.0, 2.5], "axis": [0.3, 0.4, 0.866], "radius": 1.25}
SPHERE = {"type": "sphere", "center": [1.0, 2.0, -3.0], "radius": 0.8}


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


# --- pyRANSAC-3D-style NumPy RANSAC (same algorithms as its Cylinder and Sphere classes) --------

def ransac_cylinder(points, threshold, iterations, rng):
    """3 random points: the axis is the normal of their plane, the circle through them gives the
    centre and radius; a point is an inlier when | distance to the axis - radius | <= threshold."""
    best = (None, None, None, np.empty(0, dtype=int))
    n = len(points)
    for _ in range(iterations):
        p = points[rng.choice(n, 3, replace=False)]
        a, b = p[1] - p[0], p[2] - p[0]
        axis = np.cross(a, b)
        if np.linalg.norm(axis) == 0:
            continue
        axis = unit(axis)
        # circumcentre of the triangle, in its plane
        ab = np.cross(a, b)
        centre = p[0] + (np.dot(a, a) * np.cross(b, ab) + np.dot(b, b) * np.cross(ab, a)) / (2 * np.dot(ab, ab))
        radius = np.linalg.norm(p[0] - centre)
        d = np.linalg.norm(np.cross(points - centre, axis), axis=1)
        inliers = np.flatnonzero(np.abs(d - radius) <= threshold)
        if len(inliers) > len(best[3]):
            best = (centre, axis, radius, inliers)
    return best


def ransac_sphere(points, threshold, iterations, rng):
    """4 random points: the sphere through them (a linear system); inliers | |x - c| - r | <= threshold."""
    best = (None, None, np.empty(0, dtype=int))
    n = len(points)
    for _ in range(iterations):
        p = points[rng.choice(n, 4, replace=False)]
        # |x|^2 = 2 c.x + (r^2 - |c|^2): linear in (c, k)
        A = np.column_stack([2 * p, np.ones(4)])
        try:
            sol = np.linalg.solve(A, np.sum(p * p, axis=1))
        except np.linalg.LinAlgError:
            continue
        centre = sol[:3]
        radius = np.sqrt(sol[3] + centre @ centre)
        inliers = np.flatnonzero(np.abs(np.linalg.norm(points - centre, axis=1) - radius) <= threshold)
        if len(inliers) > len(best[2]):
            best = (centre, radius, inliers)
    return best


def timed(f, *args, **kwargs):
    start = time.perf_counter()
    result = f(*args, **kwargs)
    return time.perf_counter() - start, result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fit-timing", required=True, help="path of the built bench/fit_timing")
    parser.add_argument("--repeats", type=int, default=10)
    parser.add_argument("--blocks", type=int, default=3)
    parser.add_argument("--ransac-iterations", type=int, default=1000)
    args = parser.parse_args()

    truth = implicitfit.Model.from_json(model_text(CYLINDER))
    points, normals = implicitfit.sample(truth, 100_000, noise=NOISE, outliers=0.1, seed=3)
    with tempfile.TemporaryDirectory() as tmp:
        cloud = Path(tmp) / "cylinder.xyz"
        np.savetxt(cloud, np.hstack([points, normals]), fmt="%.17g")
        points, normals = implicitfit.read_cloud(str(cloud))  # exactly what fit_timing reads

        python_s, cpp_s, cpp_model, in_call, cpp_untimed = [], [], None, [], []
        for _ in range(args.blocks):
            out = subprocess.run([args.fit_timing, str(cloud), "cylinder", "1", str(args.repeats)],
                                 check=True, capture_output=True, text=True).stdout
            result = json.loads(out)
            cpp_s += result["seconds"]
            cpp_untimed += result["untimed"]
            cpp_model = result["model"]
            for _ in range(args.repeats):
                seconds, (model, report) = timed(implicitfit.fit, points, normals, kind="cylinder", seed=1)
                python_s.append(seconds)
                in_call.append(seconds - report["seconds"])  # everything but the library's own fit
        identical = model.to_json() == cpp_model

    py_med, cpp_med = statistics.median(python_s), statistics.median(cpp_s)
    print(f"cloud: 100000 points on a cylinder (r = 1.25, noise {NOISE}, 10% outliers), with normals")
    print(f"C++ FitPrimitive   median {cpp_med:.4f} s  min {min(cpp_s):.4f} s  ({len(cpp_s)} runs)")
    print(f"implicitfit.fit    median {py_med:.4f} s  min {min(python_s):.4f} s  ({len(python_s)} runs)")
    print(f"Python overhead    median {100 * (py_med / cpp_med - 1):+.2f} %  min {100 * (min(python_s) / min(cpp_s) - 1):+.2f} %")
    print(f"same model from both (bit for bit): {identical}")
    # Within each call: wall time minus the fit's own time (report["seconds"], timed inside
    # FitPrimitive). From Python that is the array conversion, GIL hand-over, model and report
    # objects plus what the fitter leaves untimed (validation, Ceres teardown), which fit_timing
    # measures the same way in C++; the difference is the Python overhead, measured within calls
    # and so insensitive to the load drifting between runs, unlike the ratio of medians above.
    overhead = statistics.median(in_call) - statistics.median(cpp_untimed)
    fit_only = statistics.median(p - o for p, o in zip(python_s, in_call))
    print(f"untimed by the fitter: from Python median {1000 * statistics.median(in_call):.2f} ms, "
          f"from C++ {1000 * statistics.median(cpp_untimed):.2f} ms")
    print(f"Python overhead    {1000 * overhead:.2f} ms per call = {100 * overhead / fit_only:.2f} % of the fit "
          f"({1000 * fit_only:.1f} ms), medians")
    # Minima: the runs least disturbed by other processes (preemption only ever adds time).
    overhead = min(in_call) - min(cpp_untimed)
    fit_only = min(p - o for p, o in zip(python_s, in_call))
    print(f"Python overhead    {1000 * overhead:.2f} ms per call = {100 * overhead / fit_only:.2f} % of the fit "
          f"({1000 * fit_only:.1f} ms), minima")

    seconds = min(timed(implicitfit.Model.from_json(model_text(CYLINDER)).evaluate, points)[0] for _ in range(5))
    print(f"(for scale: evaluating f at the 100000 points from Python takes {1000 * seconds:.2f} ms)")

    rng = np.random.default_rng(0)
    axis_truth = unit(CYLINDER["axis"])
    rs_s, (centre, axis, radius, inliers) = timed(ransac_cylinder, points, 3 * NOISE, args.ransac_iterations, rng)
    p = model.parameters

    def axis_error(a):
        return np.degrees(np.arccos(min(1.0, abs(unit(a) @ axis_truth))))

    def line_distance(point_on_line, a):
        d = np.asarray(CYLINDER["point"]) - point_on_line
        return np.linalg.norm(d - (d @ unit(a)) * unit(a))

    print("\n| cylinder, 10^5 points | time (s) | axis error (deg) | radius error | axis offset | inliers |")
    print("|---|---|---|---|---|---|")
    print(f"| implicitfit.fit | {py_med:.3f} | {axis_error(p['axis']):.2g} | {abs(p['radius'] - 1.25):.2g} | "
          f"{line_distance(p['point'], p['axis']):.2g} | {report['inliers']} |")
    print(f"| NumPy RANSAC (pyRANSAC-3D style), {args.ransac_iterations} iterations | {rs_s:.3f} | "
          f"{axis_error(axis):.2g} | {abs(radius - 1.25):.2g} | {line_distance(centre, axis):.2g} | {len(inliers)} |")

    sphere = implicitfit.Model.from_json(model_text(SPHERE))
    spoints, snormals = implicitfit.sample(sphere, 100_000, noise=NOISE, outliers=0.1, seed=3)
    fit_s, (smodel, sreport) = timed(implicitfit.fit, spoints, snormals, kind="sphere", seed=1)
    rs_s, (scentre, sradius, sinliers) = timed(ransac_sphere, spoints, 3 * NOISE, args.ransac_iterations, rng)
    sp = smodel.parameters
    print("\n| sphere, 10^5 points | time (s) | centre error | radius error | inliers |")
    print("|---|---|---|---|---|")
    print(f"| implicitfit.fit | {fit_s:.3f} | {np.linalg.norm(sp['center'] - SPHERE['center']):.2g} | "
          f"{abs(sp['radius'] - SPHERE['radius']):.2g} | {sreport['inliers']} |")
    print(f"| NumPy RANSAC (pyRANSAC-3D style), {args.ransac_iterations} iterations | {rs_s:.3f} | "
          f"{np.linalg.norm(scentre - SPHERE['center']):.2g} | {abs(sradius - SPHERE['radius']):.2g} | {len(sinliers)} |")


if __name__ == "__main__":
    main()
