"""python/implicitfit.pyi against the built module: the same public names, and every function
and method with the same parameters (names, order, defaults) as its pybind11 signature."""
import ast
import os
import re
from pathlib import Path

import implicitfit

STUBS = Path(os.environ["IMPLICITFIT_SOURCE_DIR"]) / "python" / "implicitfit.pyi"


def stub_tree():
    return ast.parse(STUBS.read_text(encoding="utf-8"))


def split_top_level(text):
    """Splits "a: x = 1, b: List[int, str] = None" at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:])
    return [p.strip() for p in parts]


def pybind_parameters(obj, name):
    """[(name, default or None)] from the first docstring line "name(a: T, b: T = d) -> R"."""
    first = obj.__doc__.splitlines()[0]
    m = re.match(re.escape(name) + r"\((.*)\) ->", first)
    assert m, f"{name}: no pybind11 signature in {first!r}"
    out = []
    for part in split_top_level(m.group(1)):
        head, _, default = part.partition("=")
        out.append((head.split(":")[0].strip(), default.strip() or None))
    return out


def stub_parameters(func):
    """[(name, default or None)]; keyword-only parameters after ("*", None), as pybind11 writes
    them."""
    args = func.args
    names = [a.arg for a in args.posonlyargs + args.args]
    defaults = [None] * (len(names) - len(args.defaults)) + [ast.literal_eval(d)
                                                             for d in args.defaults]
    out = list(zip(names, defaults))
    if args.kwonlyargs:
        out.append(("*", None))
        out += [(a.arg, None if d is None else ast.literal_eval(d))
                for a, d in zip(args.kwonlyargs, args.kw_defaults)]
    return out


def same(stub, bound, where):
    assert [n for n, _ in stub] == [n for n, _ in bound], f"{where}: parameters differ"
    for (n, sd), (_, bd) in zip(stub, bound):
        value = None if bd is None else ast.literal_eval(bd)
        assert (sd, type(sd)) == (value, type(value)), f"{where}({n}): default {sd!r} vs {bd}"


def test_the_stubs_name_exactly_the_public_names_of_the_module():
    tree = stub_tree()
    stubbed = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed.add(node.name)
        elif isinstance(node, ast.AnnAssign) and node.target.id == "__version__":
            stubbed.add("__version__")
    public = {n for n in dir(implicitfit) if not n.startswith("_")} | {"__version__"}
    assert stubbed == public


def test_every_function_has_the_module_signature():
    functions = [n for n in stub_tree().body if isinstance(n, ast.FunctionDef)]
    assert len(functions) >= 7
    for func in functions:
        same(stub_parameters(func), pybind_parameters(getattr(implicitfit, func.name), func.name),
             func.name)


def test_every_model_member_has_the_module_signature():
    (cls,) = [n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "Model"]
    members = {n.name: n for n in cls.body if isinstance(n, ast.FunctionDef)}
    bound = {n for n in dir(implicitfit.Model) if not n.startswith("_")}
    assert set(members) == bound
    for name, func in members.items():
        attr = getattr(implicitfit.Model, name)
        is_property = any(getattr(d, "id", None) == "property" for d in func.decorator_list)
        assert is_property == isinstance(attr, property), name
        if is_property:
            continue
        stub = stub_parameters(func)
        is_static = any(getattr(d, "id", None) == "staticmethod" for d in func.decorator_list)
        if not is_static:
            assert stub[0][0] == "self", name
        same(stub, pybind_parameters(attr, name), "Model." + name)


def test_every_result_class_has_the_module_attributes():
    classes = [n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name != "Model"]
    assert {c.name for c in classes} == {"FitResult", "DetectResult", "DetectedPrimitive",
                                         "ReconstructResult", "SampleResult"}
    for cls in classes:
        stubbed = {n.target.id for n in cls.body if isinstance(n, ast.AnnAssign)}
        bound = {n for n in dir(getattr(implicitfit, cls.name)) if not n.startswith("_")}
        assert stubbed == bound, cls.name
        for name in stubbed:
            assert isinstance(getattr(getattr(implicitfit, cls.name), name), property), name


def test_the_version_is_the_packages():
    assert re.fullmatch(r"\d+\.\d+\.\d+", implicitfit.__version__)
