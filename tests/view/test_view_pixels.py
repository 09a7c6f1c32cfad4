"""Pages of `implicitfit view` drawn by a real browser: headless Chromium takes screenshots of the
pages the command line writes, and the assertions are on the pixels (tests/view/browser.py
decodes the PNGs), never on the HTML text. Expected values come from the inputs (labels written
here, a sphere's projection computed in closed form), not from the viewer.

Run by CTest (tests/view/CMakeLists.txt); by hand:
  IMPLICITFIT_CLI=build/apps/implicitfit /usr/bin/python3 -m pytest tests/view
Every test skips when Chromium is not installed."""
import json
import math
import os
import random
import subprocess
from pathlib import Path

import pytest

import browser

pytestmark = pytest.mark.skipif(browser.missing() is not None,
                                reason=str(browser.missing()))

W, H = 400, 300
BACKGROUND = (255, 255, 255)
INSIDE = (0xd0, 0x3a, 0x2f)  # the documented colour of a surface's inside (docs/view.md)


def cli(*args):
    r = subprocess.run([os.environ["IMPLICITFIT_CLI"], *map(str, args)], capture_output=True,
                       text=True, timeout=300)
    return r


def view(out, *inputs, options=()):
    r = cli("view", *inputs, "--out", out, "--quiet", *options)
    assert r.returncode == 0, r.stderr
    return out


def write_ply(path, points, labels=None, residuals=None):
    props = "property double x\nproperty double y\nproperty double z\n"
    props += "property int label\n" if labels is not None else ""
    props += "property double residual\n" if residuals is not None else ""
    lines = []
    for i, p in enumerate(points):
        row = [repr(c) for c in p]
        if labels is not None:
            row.append(str(labels[i]))
        if residuals is not None:
            row.append(repr(residuals[i]))
        lines.append(" ".join(row))
    path.write_text(f"ply\nformat ascii 1.0\nelement vertex {len(points)}\n{props}end_header\n"
                    + "\n".join(lines) + "\n")
    return path


def write_model(path, root):
    path.write_text(json.dumps({"format": "implicitfit-model", "version": 1, "root": root}))
    return path


def pixels(page, tmp_path, fragment, name="shot.png"):
    png = browser.screenshot(page, tmp_path / name, W, H, fragment)
    _, _, rows = browser.read_png(png)
    return rows


def count(rows, colour):
    return browser.colour_counts(rows)[colour]


def foreground(rows):
    counts = browser.colour_counts(rows)
    return sum(n for c, n in counts.items() if c != BACKGROUND)


def patches(n_labelled, unassigned_patch=True, per_patch=1500, seed=4):
    """Square patches in the plane z = 0 on a 4 x 2 grid, patch k labelled k, one labelled -1."""
    rng = random.Random(seed)
    points, labels = [], []
    slots = n_labelled + (1 if unassigned_patch else 0)
    for k in range(slots):
        cx, cy = (k % 4) * 1.0, (k // 4) * 1.0
        for _ in range(per_patch):
            points.append((cx + rng.uniform(-0.35, 0.35), cy + rng.uniform(-0.35, 0.35), 0.0))
            labels.append(k if k < n_labelled else -1)
    return points, labels


def test_a_segmentation_of_n_primitives_shows_n_distinct_colours(tmp_path):
    n = 6
    points, labels = patches(n)
    page = view(tmp_path / "seg.html", write_ply(tmp_path / "seg.ply", points, labels))
    top = "ui=0&el=89.9&az=-90"
    rows = pixels(page, tmp_path, top)
    counts = browser.colour_counts(rows)
    seen = {c: k for c, k in counts.items() if c != BACKGROUND and k >= 30}
    # n primitive colours and the grey of the unassigned patch; no other pixel at all (flat
    # colours, no blending).
    assert len(seen) == n + 1, seen
    assert sum(counts.values()) - counts[BACKGROUND] == sum(seen.values())
    for a in seen:  # visibly distinct: far apart in RGB
        for b in seen:
            if a < b:
                assert math.dist(a, b) >= 40, (a, b)
    # Hiding the unassigned points leaves exactly the n primitive colours.
    rows = pixels(page, tmp_path, top + "&unassigned=0", "hidden.png")
    seen_hidden = {c for c, k in browser.colour_counts(rows).items() if c != BACKGROUND and k >= 30}
    assert len(seen_hidden) == n and seen_hidden < set(seen)


def test_residual_colours_tell_inside_from_outside(tmp_path):
    points, _ = patches(2, unassigned_patch=False, per_patch=3000)
    residuals = [-0.01 if p[0] < 0.5 else 0.01 for p in points]  # left patch inside, right out
    page = view(tmp_path / "res.html", write_ply(tmp_path / "res.ply", points, None, residuals))
    rows = pixels(page, tmp_path, "ui=0&el=89.9&az=-90")
    left = right = 0
    for row in rows:
        for x in range(W):
            r, g, b = row[3 * x:3 * x + 3]
            if (r, g, b) == BACKGROUND:
                continue
            if x < W // 2:
                left += b > r + 60  # blue: f < 0
            else:
                right += r > b + 60  # red: f > 0
    assert left > 2000 and right > 2000


def sphere_share(radius, distance, fov_deg=30.0):
    """Share of a W x H frame covered by a sphere seen from `distance` (centre on the axis):
    its silhouette is a circle of angular radius asin(R/d)."""
    f = (H / 2) / math.tan(math.radians(fov_deg) / 2)
    r = f * math.tan(math.asin(radius / distance))
    return math.pi * r * r / (W * H)


def disc_share(radius, distance, fov_deg=30.0):
    """Share covered by a disc facing the camera at `distance`."""
    f = (H / 2) / math.tan(math.radians(fov_deg) / 2)
    r = f * radius / distance
    return math.pi * r * r / (W * H)


SPHERE = {"type": "sphere", "center": [1, 2, 3], "radius": 2}


def test_a_mesh_covers_the_share_of_the_frame_its_projection_predicts(tmp_path):
    page = view(tmp_path / "sphere.html", write_model(tmp_path / "sphere.json", SPHERE))
    d = 10.0
    rows = pixels(page, tmp_path, f"ui=0&camera={1 + d},2,3&target=1,2,3")
    share = foreground(rows) / (W * H)
    assert share == pytest.approx(sphere_share(2, d), rel=0.03)
    # The default framing: the box's bounding sphere (radius sqrt(3) R) fills the view.
    rows = pixels(page, tmp_path, "ui=0", "default.png")
    fit = math.sqrt(3) * 2 / math.sin(math.radians(15))
    assert foreground(rows) / (W * H) == pytest.approx(sphere_share(2, fit), rel=0.05)


def test_the_clipping_plane_shows_the_inside_and_moving_it_changes_the_picture(tmp_path):
    page = view(tmp_path / "sphere.html", write_model(tmp_path / "sphere.json", SPHERE))
    d = 10.0
    camera = f"ui=0&camera={1 + d},2,3&target=1,2,3"
    closed = pixels(page, tmp_path, camera, "closed.png")
    assert count(closed, INSIDE) == 0  # a closed surface shows only its outside
    half = pixels(page, tmp_path, camera + "&clip=x,0.5", "half.png")
    # Cut through the centre: the camera looks into the back half, its inside fills the cut disc.
    assert count(half, INSIDE) / (W * H) == pytest.approx(disc_share(2, d), rel=0.04)
    quarter = pixels(page, tmp_path, camera + "&clip=x,0.25", "quarter.png")
    # Cut at x = 1 - R/2: a disc of radius R sqrt(3)/2 at distance d + R/2.
    assert count(quarter, INSIDE) / (W * H) == pytest.approx(
        disc_share(2 * math.sqrt(3) / 2, d + 1), rel=0.04)
    changed = sum(a != b for ra, rb in zip(half, quarter) for a, b in zip(ra, rb))
    assert changed > 0.02 * W * H * 3


def test_an_empty_scene_draws_only_background(tmp_path):
    points, labels = patches(3)
    page = view(tmp_path / "seg.html", write_ply(tmp_path / "seg.ply", points, labels),
                write_model(tmp_path / "sphere.json", SPHERE))
    rows = pixels(page, tmp_path, "ui=0&hide=all")
    assert foreground(rows) == 0
    # A model whose zero set misses the box: a layer without triangles, nothing drawn.
    far = view(tmp_path / "far.html", tmp_path / "sphere.json",
               options=("--box", "10,10,10,11,11,11"))
    rows = pixels(far, tmp_path, "ui=0", "far.png")
    assert foreground(rows) == 0


def test_view_png_draws_the_page_itself(tmp_path):
    model = write_model(tmp_path / "sphere.json", SPHERE)
    png = tmp_path / "picture.png"
    r = cli("view", model, "--png", png, "--size", f"{W}x{H}", "--hide-panel", "--quiet",
            "--option", "camera=11,2,3", "--option", "target=1,2,3")
    assert r.returncode == 0, r.stderr
    assert not (tmp_path / "sphere.html").exists()
    _, _, rows = browser.read_png(png)
    assert len(rows) == H and len(rows[0]) == 3 * W
    assert foreground(rows) / (W * H) == pytest.approx(sphere_share(2, 10), rel=0.03)
