#!/usr/bin/env python3
"""The JSON Schemas of docs/schemas/ hold for what the commands write (docs/formats.md).

Usage: check_schemas.py CLI [SOURCE_DIR]   (CLI: the built `implicitfit`; SOURCE_DIR: default this
file's repository). Exit 0 when every check holds, 1 with one line per problem, 77 (skipped) when
this interpreter has no `jsonschema` module (Debian: python3-jsonschema, for /usr/bin/python3).

  1. the three schemas are valid draft 2020-12 schemas;
  2. the commands run on the bundled clouds (datasets/data) and on a cloud `sample` draws, into a
     temporary folder: fit of several kinds (two failing, whose reports say so), detect on the
     .xyz, .ply and .pcd clouds, reconstruct with and without a scene, verify (a verified model
     and a refused one), check --json, design, batch; every model, scene and report they write
     (and the JSON reconstruct, verify and check print) validates against its schema, each
     report also against the definition of its kind;
  3. every model of tests/fuzz/model_corpus that the tool accepts (`eval` exit 0) validates;
  4. one hand-made model per node type and form (the types of the reader's tables in
     model/model.cc and model/primitives/primitive_kinds.cc, which must be the schema's): the
     tool and the schema accept it; for each copy with one key dropped or one unknown key added
     (at every object of the document) the tool and the schema agree (the schema is as strict as
     the reader on keys); each copy with an array one element longer or shorter, a number
     negated or written as a string, that the tool accepts, the schema accepts (the schema is
     never stricter than the reader);
  5. hand-made invalid models, scenes and reports (unknown key, missing radius, wrong array
     lengths, out-of-range values, wrong types) are refused by the schema, and the models and
     scenes by the tool too; the documented limits the spline reader does not check
     (docs/formats.md) are refused by the schema and still accepted by the tool.
"""
import copy
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    print("check_schemas: skipped: %s has no jsonschema module (Debian: python3-jsonschema)"
          % sys.executable)
    sys.exit(77)

if len(sys.argv) < 2:
    sys.exit(__doc__)
CLI = os.path.abspath(sys.argv[1])
ROOT = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else
                    pathlib.Path(__file__).resolve().parent.parent.parent).resolve()
SCHEMAS = ROOT / "docs" / "schemas"
DATA = ROOT / "datasets" / "data"
REPORT_KINDS = ("fit", "detect", "reconstruct", "verify", "check")

problems = []
validated = {"model": 0, "scene": 0, "report": 0}  # documents the commands wrote or printed
hand_made = []  # valid documents written here or kept in the repository


def problem(text):
    problems.append(text)
    print("FAIL " + text)


def strict_load(text, where):
    """JSON as the tool's readers take it: no duplicate keys, no NaN or Infinity tokens."""
    def pairs(items):
        keys = [k for k, _ in items]
        if len(keys) != len(set(keys)):
            raise ValueError("duplicate key in " + where)
        return dict(items)

    def constant(name):
        raise ValueError("%s: non-standard JSON constant %s" % (where, name))
    return json.loads(text, object_pairs_hook=pairs, parse_constant=constant)


# --- 1. the schemas -------------------------------------------------------------------------
# Each schema under its file's URI, so that the relative references between the files of
# docs/schemas (the scene's "model.schema.json#/$defs/node") resolve.
schema = {}
uri = {}
for name in ("model", "scene", "report"):
    path = SCHEMAS / (name + ".schema.json")
    schema[name] = strict_load(path.read_text(), str(path))
    jsonschema.Draft202012Validator.check_schema(schema[name])
    uri[name] = path.as_uri()
    schema[name]["$id"] = uri[name]
try:  # jsonschema >= 4.18
    import referencing
    import referencing.jsonschema
    registry = referencing.Registry().with_resources(
        (uri[n], referencing.Resource.from_contents(
            schema[n], default_specification=referencing.jsonschema.DRAFT202012))
        for n in schema)
    references = {"registry": registry}
    jsonschema.Draft202012Validator({}, **references)
except (ImportError, TypeError):  # Debian 12's 4.10: no registries yet
    references = None


def validator(name, definition=None):
    """A validator of the schema `name`, or of one of its $defs."""
    s = schema[name]
    if definition:
        s = {"$ref": uri[name] + "#/$defs/" + definition}
    if references:
        return jsonschema.Draft202012Validator(s, **references)
    resolver = jsonschema.RefResolver(base_uri=s.get("$id", ""), referrer=s,
                                      store={uri[n]: schema[n] for n in schema})
    return jsonschema.Draft202012Validator(s, resolver=resolver)


VALIDATOR = {name: validator(name) for name in schema}
KIND_VALIDATOR = {kind: validator("report", kind) for kind in REPORT_KINDS}


def errors(v, document):
    return ["%s: %s" % (e.json_path, e.message[:200]) for e in v.iter_errors(document)]


def validate(document, name, where, kind=None, written=True):
    """`document` must satisfy schema `name` (and, for a report, the definition of its kind).
    `written`: the commands wrote it (counted in the summary)."""
    found = errors(VALIDATOR[name], document)
    if kind:
        found += ["(as a %s report) %s" % (kind, e)
                  for e in errors(KIND_VALIDATOR[kind], document)]
    for e in found[:5]:
        problem("%s does not match %s.schema.json: %s" % (where, name, e))
    if not found:
        if written:
            validated[name] += 1
        else:
            hand_made.append(where)


def validate_file(path, name, kind=None, written=True):
    if not os.path.isfile(path):
        problem("%s: not written" % path)
        return
    with open(path) as f:
        text = f.read()
    try:
        document = strict_load(text, path)
    except ValueError as e:
        problem("%s: not JSON: %s" % (path, e))
        return
    validate(document, name, os.path.basename(path), kind, written)


def run(args, expect=(0,), stdout_json=None):
    """Runs the CLI; the exit code must be one of `expect`. With stdout_json (a report kind),
    standard output is a JSON report of that kind."""
    r = subprocess.run([CLI] + [str(a) for a in args], capture_output=True, text=True)
    if r.returncode not in expect:
        problem("implicitfit %s: exit %d, expected %s: %s"
                % (" ".join(map(str, args)), r.returncode, expect, r.stderr.strip()[-300:]))
        return r
    if stdout_json:
        try:
            document = strict_load(r.stdout, "stdout of " + str(args[0]))
        except ValueError as e:
            problem("implicitfit %s: standard output is not JSON: %s" % (args[0], e))
            return r
        validate(document, "report", "standard output of implicitfit " + str(args[0]),
                 stdout_json)
    return r


def model_document(root):
    return {"format": "implicitfit-model", "version": 1, "root": root}


# One valid model per node type and form (the reader must accept every one).
SPHERE = {"type": "sphere", "center": [0, 0, 0], "radius": 1}
PLANE = {"type": "plane", "normal": [0, 0, 1], "offset": 0}
FEATURE = {"point": [0, 0, 0.4], "width": 0.3, "depth": 0.25, "radius": 0.2, "flare": 0.5}
CUBE_MESH = {"type": "bernstein_mesh", "degree": 1, "continuity": 0,
             "grid": {"origin": [-1, -1, -1], "cell": 2, "cells": [1, 1, 1]},
             "control_points": [1.0] * 24}
EVERY_NODE = {
    "plane": PLANE,
    "plane through a point": {"type": "plane", "point": [0, 0, 1], "normal": [0, 0, 2]},
    "sphere": dict(SPHERE, name="ball", fixed=["radius"]),
    "cylinder": {"type": "cylinder", "point": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.5},
    "cone": {"type": "cone", "apex": [0, 0, 0], "axis": [0, 0, 1], "half_angle": 0.4},
    "torus": {"type": "torus", "center": [0, 0, 0], "axis": [0, 0, 1], "major_radius": 1,
              "minor_radius": 0.25},
    "ellipsoid": {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 2, 3],
                  "axes": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
    "quadric": {"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1]},
    "box": {"type": "box", "center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]],
            "half_sizes": [1, 0.5, 0.25]},
    "paraboloid": {"type": "paraboloid", "vertex": [0, 0, 0], "axis": [0, 0, 1],
                   "curvature": 0.5},
    "bernstein_patch": {"type": "bernstein_patch", "degree": 1,
                        "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                        "control_points": [1, -1, -1, -1]},
    "union": {"type": "union", "delta": 0.2, "epsilon": 0.1, "order": 3,
              "smoothing": "li-phillips", "children": [SPHERE, PLANE]},
    "convex intersection": {"type": "intersection", "delta": 0.2, "order": 2,
                            "smoothing": "convex", "children": [SPHERE, PLANE]},
    "difference": {"type": "difference", "delta": 0.2, "epsilon": 0.2, "order": 0,
                   "fixed": ["delta"], "children": [SPHERE, PLANE]},
    "complement": {"type": "complement", "children": [SPHERE]},
    "morph": {"type": "morph", "t": 0.3, "children": [SPHERE, dict(SPHERE, radius=2)]},
    "gaussian blobs": {"type": "blobs", "centers": [[0, 0, 0], [1, 0, 0]], "weights": [1, 1],
                       "widths": [1, 1], "threshold": 0.5, "kernel": "gaussian"},
    "h_n blob": {"type": "blobs", "centers": [[0, 0, 0]], "weights": [1], "widths": [1],
                 "threshold": 0.5, "kernel": "h_n", "order": 3},
    "point skeleton": {"type": "skeleton_offset", "skeleton": {"points": [[0, 0, 0]]},
                       "radius": 1},
    "capsule": {"type": "skeleton_offset", "radius": 0.2,
                "skeleton": {"segments": [[[0, 0, 0], [1, 0, 0]]]}},
    "tube": {"type": "skeleton_offset", "radius": 0.2,
             "skeleton": {"polyline": [[0, 0, 0], [1, 0, 0], [1, 1, 0]]}},
    "triangle skeleton with features": {
        "type": "skeleton_offset", "radius": 0.4, "features": [FEATURE],
        "skeleton": {"triangles": [[[-2, -2, 0], [2, -2, 0], [0, 2, 0]]]},
        "fixed": ["skeleton", "features"]},
    "B-spline curve tube": {"type": "skeleton_offset", "radius": 0.1, "skeleton": {"curve": {
        "bspline": {"degree": 2, "knots": [0, 0, 0, 1, 1, 1], "weights": [1, 0.7, 1],
                    "control_points": [[0, 0, 0], [1, 1, 0], [2, 0, 0]]}}}},
    "Bezier curve tube": {"type": "skeleton_offset", "radius": 0.1, "skeleton": {"curve": {
        "bezier": {"control_points": [[0, 0, 0], [1, 1, 0], [2, 0, 0]]}}}},
    "ellipse tube": {"type": "skeleton_offset", "radius": 0.1, "skeleton": {"curve": {
        "ellipse": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 2, 0]]}}}},
    "helix tube": {"type": "skeleton_offset", "radius": 0.1, "skeleton": {"curve": {
        "helix": {"center": [0, 0, 0], "axes": [[1, 0, 0], [0, 1, 0]], "rise": [0, 0, 0.5],
                  "turns": 2}}}},
    "segment tube": {"type": "skeleton_offset", "radius": 0.1,
                     "skeleton": {"curve": {"segment": [[0, 0, 0], [1, 0, 0]]}}},
    "partition": {"type": "partition", "cuts": [[0], [], []], "epsilon": 0.1, "order": 3,
                  "children": [PLANE, dict(PLANE, offset=0.5)]},
    "partition_sequence": {"type": "partition_sequence", "epsilon": 0.1, "order": 3,
                           "separators": [{"type": "plane", "normal": [1, 0, 0], "offset": 0}],
                           "children": [PLANE, dict(PLANE, offset=0.5)]},
    "coleman_features": {"type": "coleman_features", "core_radius": 0.4,
                         "features": [dict(FEATURE, flare=0)], "children": [PLANE]},
    "coleman curve features": {
        "type": "coleman_features", "core_radius": 0.4, "fixed": ["curve_features"],
        "curve_features": [{"curve": [[0, 0, 0], [1, 0, 0]], "width": 0.3, "depth": 0.25,
                            "radius": 0.2, "flare": 1}],
        "children": [PLANE]},
    "bernstein_mesh": CUBE_MESH,
    "adaptive bernstein_mesh": dict(
        CUBE_MESH, continuity=1, c0_faces=[[0, 1], [5, 3]], control_points=[1.0] * 192,
        grid={"origin": [-1, -1, -1], "cell": 2, "cells": [1, 1, 1], "splits": "100000000"}),
    "NURBS surface": {"type": "bspline_surface", "degree": [2, 1], "knots_u": [0, 0, 0, 1, 1, 1],
                      "knots_v": [0, 0, 1, 1],
                      "control_points": [[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]],
                                         [[0, 1, 0], [0, 1, 1]]],
                      "weights": [[1, 1], [0.7, 0.7], [1, 1]]},
    "bspline_volume": {"type": "bspline_volume", "degree": 1, "box": [0, 0, 0, 1, 1, 1],
                       "cells": [1, 1, 1], "coefficients": [-1, 1, 1, 1, 1, 1, 1, 1]},
}
# Key mutants where the reader and the schema disagree for a reason a schema cannot state: the
# control point count of an adaptive mesh follows from its split flags.
KNOWN_DISAGREEMENTS = {("adaptive bernstein_mesh", "splits dropped at ('root', 'grid')")}
CLAIMS = {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]},
          "verification": {"verified": False, "reason": "a reason"}}


def objects(value, at=()):
    """Every object of a document with its path."""
    if isinstance(value, dict):
        yield at, value
        for k, v in value.items():
            yield from objects(v, at + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from objects(v, at + (i,))


def at_path(document, at):
    for k in at:
        document = document[k]
    return document


def key_mutants(document):
    """Copies of the document with one key dropped or one unknown key added."""
    for at, obj in objects(document):
        m = copy.deepcopy(document)
        at_path(m, at)["unknown_key"] = 1
        yield "unknown key at %s" % (at,), m
        for key in obj:
            m = copy.deepcopy(document)
            del at_path(m, at)[key]
            yield "%s dropped at %s" % (key, at), m


def value_mutants(document):
    """Copies of the document with one array grown or shrunk by an element, or one number
    negated (-x - 1) or written as a string (of an array of numbers, only the first)."""
    def places(value, at=()):
        if isinstance(value, dict):
            for k, v in value.items():
                yield from places(v, at + (k,))
        elif isinstance(value, list):
            yield at, value
            for i, v in enumerate(value):
                if i == 0 or not isinstance(v, (int, float)):
                    yield from places(v, at + (i,))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            yield at, value
    for at, value in places(document):
        if isinstance(value, list):
            if value:
                m = copy.deepcopy(document)
                at_path(m, at).append(copy.deepcopy(value[-1]))
                yield "%s grown" % (at,), m
                m = copy.deepcopy(document)
                at_path(m, at).pop()
                yield "%s shrunk" % (at,), m
        else:
            for what, new in (("negated", -value - 1), ("as a string", str(value))):
                m = copy.deepcopy(document)
                at_path(m, at[:-1])[at[-1]] = new
                yield "%s %s" % (at, what), m


with tempfile.TemporaryDirectory(prefix="check_schemas.") as tmp:
    t = pathlib.Path(tmp)

    def write(name, document):
        path = t / name
        path.write_text(document if isinstance(document, str) else json.dumps(document))
        return path

    def tool_accepts(path):
        r = subprocess.run([CLI, "eval", str(path), str(points)], capture_output=True, text=True)
        if r.returncode not in (0, 2):
            problem("implicitfit eval %s: exit %d: %s" % (path, r.returncode, r.stderr[-200:]))
        return r.returncode == 0

    points = write("points.txt", "0 0 0\n0.5 0.25 0.1\n")
    sphere_cloud = DATA / "cgal_sphere_single.xyz"
    crease_cloud = DATA / "cgal_fin90_two_planes_crease.xyz"

    # --- 2. what the commands write -----------------------------------------------------------
    planes = [{"type": "plane", "normal": [s if a == i else 0 for i in range(3)], "offset": h}
              for a, h in enumerate((0.5, 0.4, 0.3)) for s in (-1, 1)]
    box = write("box.json", model_document({"type": "intersection", "delta": 0.1,
                                            "epsilon": 0.05, "order": 0, "children": planes}))
    validate_file(box, "model", written=False)
    run(["sample", box, "--count", 2000, "--noise", 0.002, "--seed", 5, "--out", t / "box.xyz"])
    box_cloud = t / "box.xyz"

    fits = [("sphere", sphere_cloud, ["--model", "sphere"]),
            ("cylinder-ls", crease_cloud, ["--model", "cylinder", "--estimator", "least-squares"]),
            ("sphere-zone", sphere_cloud, ["--model", "sphere", "--estimator", "minimum-zone"]),
            ("patch", sphere_cloud, ["--model", "quadric-patch"]),
            ("convex-patch", sphere_cloud, ["--model", "quadric-patch", "--convex"]),
            ("patch-mesh", sphere_cloud, ["--model", "patch-mesh", "--cells", 2]),
            ("volume", sphere_cloud, ["--model", "bspline-volume", "--cells", 2, "--convex"]),
            ("surface", sphere_cloud, ["--model", "bspline-surface", "--grid", "4x4"]),
            ("shape-box", box_cloud, ["--model", "box"]),
            ("tree", box_cloud, ["--init", box]),
            ("partition", box_cloud, ["--model", "partition", "--grid", "2x1x1"])]
    for name, cloud, options in fits:
        run(["fit", cloud] + options + ["--out", t / (name + ".json"),
                                        "--report", t / (name + ".report.json")])
        validate_file(t / (name + ".json"), "model")
        validate_file(t / (name + ".report.json"), "report", "fit")
    # A fit that fails (exit 1) writes its report, saying so, and no model.
    run(["fit", crease_cloud, "--model", "torus", "--out", t / "torus.json",
         "--report", t / "torus.report.json"], expect=(1,))
    validate_file(t / "torus.report.json", "report", "fit")
    if (t / "torus.json").exists():
        problem("a failed fit wrote its model")
    # Five points: no robust start for a box; the report has only the keys every fit report has.
    five = write("five.xyz", "".join(sphere_cloud.read_text().splitlines(True)[:5]))
    run(["fit", five, "--model", "box", "--out", t / "none.json",
         "--report", t / "failed-start.report.json"], expect=(1,))
    validate_file(t / "failed-start.report.json", "report", "fit")

    for name, cloud in (("crease", crease_cloud), ("spheres", DATA / "cgal_spheres_10.ply"),
                        ("carton", DATA / "pcl_milk_carton_kinect.pcd"), ("box", box_cloud)):
        run(["detect", cloud, "--quiet", "--out", t / (name + ".scene.json"),
             "--report", t / (name + ".detect.json"), "--labels", t / (name + ".labels.txt")])
        validate_file(t / (name + ".scene.json"), "scene")
        validate_file(t / (name + ".detect.json"), "report", "detect")
    run(["detect", sphere_cloud, "--freeform", "--quiet", "--out", t / "freeform.scene.json",
         "--report", t / "freeform.detect.json"])
    validate_file(t / "freeform.scene.json", "scene")
    validate_file(t / "freeform.detect.json", "report", "detect")
    # Two points: too few for normals; the report has only the keys every detect report has.
    two = write("two.xyz", "".join(sphere_cloud.read_text().splitlines(True)[:2]))
    run(["detect", two, "--quiet", "--out", t / "two.scene.json",
         "--report", t / "two.detect.json"], expect=(1,))
    validate_file(t / "two.detect.json", "report", "detect")

    run(["reconstruct", box_cloud, "--quiet", "--out", t / "solid.json",
         "--report", t / "solid.report.json"], stdout_json="reconstruct")
    validate_file(t / "solid.json", "model")
    validate_file(t / "solid.report.json", "report", "reconstruct")
    run(["reconstruct", crease_cloud, "--quiet", "--scene", t / "crease.scene.json",
         "--out", t / "crease.solid.json", "--report", t / "crease.reconstruct.json"],
        stdout_json="reconstruct")
    validate_file(t / "crease.solid.json", "model")
    validate_file(t / "crease.reconstruct.json", "report", "reconstruct")
    run(["reconstruct", two, "--quiet", "--out", t / "two.solid.json",
         "--report", t / "two.reconstruct.json"], expect=(1,))
    validate_file(t / "two.reconstruct.json", "report", "reconstruct")

    run(["verify", t / "solid.json", box_cloud, "--quiet", "--report", t / "verify.json"],
        stdout_json="verify")
    validate_file(t / "verify.json", "report", "verify")
    run(["verify", t / "sphere.json", box_cloud, "--quiet", "--report", t / "refused.json"],
        expect=(1,), stdout_json="verify")
    validate_file(t / "refused.json", "report", "verify")

    run(["check", t / "patch.json", "--json"], stdout_json="check")
    run(["check", t / "patch.json", t / "patch-mesh.json", t / "convex-patch.json", "--json",
         "--sample", 50], stdout_json="check")
    run(["check", t / "volume.json", t / "tree.json", t / "solid.json", t / "sphere.json",
         "--json"], expect=(0, 1), stdout_json="check")
    run(["check", t / "partition.json", t / "surface.json", "--json"], expect=(0, 1),
        stdout_json="check")

    run(["design", box_cloud, "--primitive", "plane", "--count", 6, "--out", t / "design.json"])
    validate_file(t / "design.json", "model")

    for kind, report_kind in (("sphere", "fit"), ("scene", "detect"), ("solid", "reconstruct")):
        out = t / ("batch-" + kind)
        run(["batch", sphere_cloud, box_cloud, "--model", kind, "--out-dir", out],
            expect=(0, 1))
        reports = sorted(out.glob("*.report.json"))
        if len(reports) != 2:
            problem("batch --model %s wrote %d reports, expected 2" % (kind, len(reports)))
        for path in reports:
            validate_file(path, "report", report_kind)
        for path in sorted(out.glob("*.model.json")):
            validate_file(path, "model")
        for path in sorted(out.glob("*.scene.json")):
            validate_file(path, "scene")

    # --- 3. the fuzzers' model corpus ---------------------------------------------------------
    corpus = sorted((ROOT / "tests" / "fuzz" / "model_corpus").glob("*.json"))
    accepted = [path for path in corpus if tool_accepts(path)]
    for path in accepted:
        validate_file(path, "model", written=False)
    if len(accepted) < 5:
        problem("only %d of %d corpus models accepted by the tool" % (len(accepted), len(corpus)))

    # --- 4. every node type, and the keys of each ---------------------------------------------
    # The node types: the reader's (its type tables), the schema's and the samples' are one set.
    reader_types = set()
    for source in ("model/model.cc", "model/primitives/primitive_kinds.cc"):
        reader_types |= set(re.findall(r'NodeType::k\w+,\s*"(\w+)"', (ROOT / source).read_text()))
    schema_types = set(schema["model"]["$defs"]["node"]["properties"]["type"]["enum"])
    sample_types = {root["type"] for root in EVERY_NODE.values()}
    if len(reader_types) < 20 or reader_types != schema_types or schema_types != sample_types:
        problem("node types: the reader's %s, the schema's %s, the samples' %s"
                % (sorted(reader_types), sorted(schema_types), sorted(sample_types)))
    mutants = disagreements = value_checked = value_accepted = value_refused_by_both = 0
    for name, root in EVERY_NODE.items():
        document = model_document(root)
        if name == "sphere":
            document.update(CLAIMS)
        if not tool_accepts(write("node.json", document)):
            problem("the hand-made %s model is refused by the tool" % name)
        validate(document, "model", "the hand-made %s model" % name, written=False)
        for what, m in key_mutants(document):
            mutants += 1
            tool = tool_accepts(write("mutant.json", m))
            ours = VALIDATOR["model"].is_valid(m)
            if (name, what) in KNOWN_DISAGREEMENTS:
                if tool or not ours:
                    problem("%s model, %s: no longer the known disagreement" % (name, what))
                continue
            if tool != ours:
                disagreements += 1
                problem("%s model, %s: the tool %s it, the schema %s it"
                        % (name, what, "accepts" if tool else "refuses",
                           "accepts" if ours else "refuses"))
        # Lengths, signs and types: whatever the tool accepts, the schema must accept (it may
        # accept more: relations between fields are left to the reader).
        for what, m in value_mutants(document):
            value_checked += 1
            if tool_accepts(write("mutant.json", m)):
                value_accepted += 1
                if not VALIDATOR["model"].is_valid(m):
                    problem("%s model, %s: the tool accepts it, the schema refuses it: %s"
                            % (name, what, errors(VALIDATOR["model"], m)[0]))
            elif not VALIDATOR["model"].is_valid(m):
                value_refused_by_both += 1
    if mutants < 300 or value_checked < 500:
        problem("only %d key mutants and %d value mutants" % (mutants, value_checked))

    # --- 5. invalid documents -----------------------------------------------------------------
    patch = EVERY_NODE["bernstein_patch"]
    invalid_models = {
        "an unknown key": dict(SPHERE, colour="red"),
        "no radius": {"type": "sphere", "center": [0, 0, 0]},
        "a centre of 2 numbers": dict(SPHERE, center=[0, 0]),
        "a negative radius": dict(SPHERE, radius=-1),
        "a zero axis": dict(EVERY_NODE["cylinder"], axis=[0, 0, 0]),
        "3 tetrahedron vertices": dict(patch, vertices=patch["vertices"][:3]),
        "11 control points of a degree-2 patch": dict(patch, degree=2,
                                                      control_points=[1.0] * 11),
        "epsilon with convex smoothing": dict(EVERY_NODE["convex intersection"], epsilon=0.1),
        "an order of 15": dict(EVERY_NODE["union"], order=15),
        "one child of a union": dict(EVERY_NODE["union"], children=[SPHERE]),
        "a string radius": dict(SPHERE, radius="1"),
        "a number beyond 1e15": dict(SPHERE, center=[2e15, 0, 0]),
        "an order on a gaussian blob": dict(EVERY_NODE["gaussian blobs"], order=3),
        "two skeletons": {"type": "skeleton_offset", "radius": 1,
                          "skeleton": {"points": [[0, 0, 0]], "polyline": [[0, 0, 0], [1, 0, 0]]}},
        "a fixed field of another type": dict(SPHERE, fixed=["axis"]),
        "a split flag 2": dict(CUBE_MESH, grid=dict(CUBE_MESH["grid"], splits="2")),
        "a volume of 129 cells": dict(EVERY_NODE["bspline_volume"], cells=[129, 1, 1]),
    }
    for what, root in invalid_models.items():
        document = model_document(root)
        if tool_accepts(write("invalid.json", document)):
            problem("a model with %s is accepted by the tool (not an invalid case)" % what)
        if VALIDATOR["model"].is_valid(document):
            problem("a model with %s passes model.schema.json" % what)
    for what, document in {
            "version 2": dict(model_document(SPHERE), version=2),
            "an unknown top-level key": dict(model_document(SPHERE), comment="x"),
            "a reason beside verified true": dict(model_document(SPHERE),
                                                  verification={"verified": True, "reason": "x"}),
            "a bounds box of 2 numbers": dict(model_document(SPHERE),
                                              bounds={"min": [0, 0], "max": [1, 1, 1]})}.items():
        if tool_accepts(write("invalid.json", document)):
            problem("a model file with %s is accepted by the tool (not an invalid case)" % what)
        if VALIDATOR["model"].is_valid(document):
            problem("a model file with %s passes model.schema.json" % what)

    # The limits of docs/model-file.md that the spline reader does not check (docs/formats.md):
    # the schema refuses these, the tool accepts them. When the reader checks one, this list and
    # docs/formats.md lose it.
    curve_feature = EVERY_NODE["coleman curve features"]["curve_features"][0]
    unchecked_limits = {
        "a volume coefficient of 1e16": dict(EVERY_NODE["bspline_volume"],
                                             coefficients=[-1, 1, 1, 1, 1, 1, 1, 1e16]),
        "a surface control point at 1e16": dict(EVERY_NODE["NURBS surface"], control_points=[
            [[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1e16]]]),
        "a curve segment to 1e16": dict(EVERY_NODE["segment tube"],
                                        skeleton={"curve": {"segment": [[0, 0, 0], [1e16, 0, 0]]}}),
        "a curve feature of width 1e-13": dict(EVERY_NODE["coleman curve features"],
                                               curve_features=[dict(curve_feature, width=1e-13)]),
    }
    for what, root in unchecked_limits.items():
        document = model_document(root)
        if not tool_accepts(write("limit.json", document)):
            problem("the tool now refuses a model with %s: drop it from docs/formats.md and from "
                    "this list" % what)
        if VALIDATOR["model"].is_valid(document):
            problem("a model with %s passes model.schema.json" % what)

    scene = strict_load((t / "crease.scene.json").read_text(), "crease.scene.json")
    invalid_scenes = {}
    s = copy.deepcopy(scene)
    s["primitives"][0]["colour"] = "red"
    invalid_scenes["an unknown primitive key"] = s
    s = copy.deepcopy(scene)
    s["primitives"][0]["normal_side"] = "sideways"
    invalid_scenes["a normal side 'sideways'"] = s
    s = copy.deepcopy(scene)
    del s["unassigned"]
    invalid_scenes["no unassigned count"] = s
    s = copy.deepcopy(scene)
    s["primitives"][0]["model"]["radius"] = 0
    invalid_scenes["a primitive of radius 0"] = s
    for what, document in invalid_scenes.items():
        r = subprocess.run([CLI, "reconstruct", crease_cloud, "--quiet", "--scene",
                            write("invalid.scene.json", document), "--out", t / "x.json"],
                           capture_output=True, text=True)
        if r.returncode != 2:
            problem("a scene with %s: reconstruct exit %d, expected 2 (refused)"
                    % (what, r.returncode))
        if VALIDATOR["scene"].is_valid(document):
            problem("a scene with %s passes scene.schema.json" % what)

    fit_report = strict_load((t / "sphere.report.json").read_text(), "sphere.report.json")
    detect_report = strict_load((t / "crease.detect.json").read_text(), "crease.detect.json")
    solid_report = strict_load((t / "solid.report.json").read_text(), "solid.report.json")
    verify_report = strict_load((t / "verify.json").read_text(), "verify.json")
    check_report = strict_load(run(["check", t / "patch.json", "--json"]).stdout, "check")
    no_verdict = copy.deepcopy(check_report)
    del no_verdict["files"][0]["verdict"]
    invalid_reports = {
        "a fit report whose success is a string": dict(fit_report, success="yes"),
        "a fit report with a negative point count": dict(fit_report, points=-1),
        "a fit report without normals": {k: v for k, v in fit_report.items() if k != "normals"},
        "a detect report without unassigned": {k: v for k, v in detect_report.items()
                                               if k != "unassigned"},
        "a report that is a list": [fit_report],
        "a reconstruct report whose bounded is an object": dict(solid_report,
                                                                bounded={"proven": True}),
        "a reconstruct report with a primitive on side 'both'": dict(
            solid_report, primitives=[dict(solid_report["primitives"][0], side="both")]),
        "a verify report without pieces": {k: v for k, v in verify_report.items()
                                           if k != "pieces"},
        "a check report whose file has no verdict": no_verdict,
        "a report without its format": {k: v for k, v in fit_report.items() if k != "format"},
        "a report of format version 2": dict(fit_report, format_version=2),
        "a report whose input has no path": dict(fit_report, input={"points": 1, "normals": ""}),
        "a fit report without its seed": {k: v for k, v in fit_report.items() if k != "seed"},
        "a report in other units": dict(detect_report, units={"length": "mm", "angle": "degree"}),
    }
    for what, document in invalid_reports.items():
        if VALIDATOR["report"].is_valid(document):
            problem("%s passes report.schema.json" % what)

total = sum(validated.values())
print("check_schemas: %d documents the commands wrote validated (%d models, %d scenes, %d "
      "reports); %d valid hand-made and corpus models (%d of %d corpus models accepted by the "
      "tool, %d node types and forms); %d key mutants, %d disagreements; %d value mutants: %d "
      "accepted by both, %d refused by both, %d refused by the tool alone (field relations)"
      % (total, validated["model"], validated["scene"], validated["report"], len(hand_made),
         len(accepted), len(corpus), len(EVERY_NODE), mutants, disagreements, value_checked,
         value_accepted, value_refused_by_both,
         value_checked - value_accepted - value_refused_by_both))
if problems:
    print("check_schemas: %d problems" % len(problems))
    sys.exit(1)
