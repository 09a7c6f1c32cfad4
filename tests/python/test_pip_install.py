"""`pip install .` works offline into a virtual environment (pyproject.toml, setup.py).

As docs/python.md says: /usr/bin/python3 -m venv --system-site-packages v, then
v/bin/pip install --no-build-isolation . (here also --no-index: nothing may come from the
network). The environment is made --without-pip and `v/bin/python -m pip` runs Debian's pip from
the system site-packages, the same pip that ensurepip would copy into it (that copy took 10 of
the test's 19 s). The package is built from a copy of the packaging files (so the source tree stays
clean) reusing this build tree (IMPLICITFIT_BUILD_DIR: the module is already built, so the
install takes seconds). Then, with no PYTHONPATH, the environment's interpreter imports the
installed module (not the build tree's), importlib.metadata knows its version, the stubs are
installed beside it, and a fit runs.
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import implicitfit

SOURCE = Path(os.environ["IMPLICITFIT_SOURCE_DIR"])
BUILD = os.environ["IMPLICITFIT_BUILD_DIR"]
PACKAGING = ["pyproject.toml", "setup.py", "README.md", "LICENSE", "CMakeLists.txt",
             "python/implicitfit.pyi"]

CHECK = r"""
import importlib.metadata, pathlib, sys
import numpy as np
import implicitfit
prefix = pathlib.Path(sys.prefix).resolve()
where = pathlib.Path(implicitfit.__file__).resolve()
assert prefix in where.parents, (where, prefix)
assert (where.parent / "implicitfit.pyi").is_file(), "no stubs beside " + str(where)
version = importlib.metadata.version("implicitfit")
assert version == implicitfit.__version__, (version, implicitfit.__version__)
truth = implicitfit.Model.from_json('{"format": "implicitfit-model", "version": 1, '
                                    '"root": {"type": "sphere", "center": [1, 2, 3], "radius": 0.5}}')
points, normals = implicitfit.sample(truth, 500, seed=3)
model, report = implicitfit.fit(points, normals, kind="sphere")
assert report["success"], report
assert abs(model.parameters["radius"] - 0.5) < 1e-9, model.parameters
print(version)
"""


def clean_environment(preload=False):
    """The environment without the build tree's module path; the sanitizer runtimes that CTest
    preloads (an instrumented module needs them) only for the interpreter that imports it, not for
    pip and the CMake build it runs."""
    drop = {"PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "PIP_INDEX_URL"}
    if not preload:
        drop |= {"LD_PRELOAD", "ASAN_OPTIONS"}
    env = {k: v for k, v in os.environ.items() if k not in drop}
    env["PIP_NO_INPUT"] = "1"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["IMPLICITFIT_BUILD_DIR"] = BUILD
    return env


def run(command, cwd, env):
    result = subprocess.run([str(c) for c in command], cwd=cwd, env=env, capture_output=True,
                            text=True, timeout=600)
    assert result.returncode == 0, (command, result.stdout[-4000:], result.stderr[-4000:])
    return result.stdout


def test_pip_installs_the_module_offline_into_a_virtual_environment(tmp_path):
    src = tmp_path / "src"
    for name in PACKAGING:
        (src / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(SOURCE / name, src / name)
    env = clean_environment()
    venv = tmp_path / "v"
    # The interpreter the module is built for (the build tree's), as the command in the docs.
    python = Path(sys.executable)
    run([python, "-m", "venv", "--system-site-packages", "--without-pip", venv], tmp_path, env)
    run([venv / "bin" / "python", "-m", "pip", "install", "--no-build-isolation", "--no-index", "."],
        src, env)
    version = run([venv / "bin" / "python", "-c", CHECK], tmp_path,
                  clean_environment(preload=True)).strip()
    assert version == implicitfit.__version__
    # The copy of the sources is untouched but for the build folder setup.py owns.
    assert sorted(p.name for p in src.iterdir()) == sorted(
        {Path(n).parts[0] for n in PACKAGING} | {"build-python"})
