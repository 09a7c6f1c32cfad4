"""Builds the `implicitfit` extension module with the project's CMake, for pyproject.toml.

The module is the CMake target implicitfit_python (python/CMakeLists.txt). build_ext configures
a build tree (build-python/ in the source tree, Release, without tests and benchmarks) unless
IMPLICITFIT_BUILD_DIR names a configured one to reuse, builds that one target there, and copies
the module and its stubs (python/implicitfit.pyi) into the wheel. The version is the one of
CMakeLists.txt's project() line, so `importlib.metadata.version("implicitfit")` and
`implicitfit.__version__` agree.
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
OWN_BUILD = ROOT / "build-python"


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*implicitfit\s+VERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no project(implicitfit VERSION x.y.z) line")
    return match.group(1)


def run(command):
    print("implicitfit:", " ".join(str(c) for c in command), flush=True)
    subprocess.run([str(c) for c in command], check=True)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = Path(os.environ.get("IMPLICITFIT_BUILD_DIR") or OWN_BUILD).resolve()
        if not (build_dir / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                         "-DIMPLICITFIT_BUILD_TESTS=OFF", "-DIMPLICITFIT_BUILD_BENCHMARKS=OFF",
                         "-DIMPLICITFIT_BUILD_PYTHON=ON", "-DPython_EXECUTABLE=" + sys.executable]
            if shutil.which("ccache"):
                configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            run(configure)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        run(["cmake", "--build", build_dir, "--target", "implicitfit_python", "-j", jobs])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        module = build_dir / "python" / ("implicitfit" + suffix)
        if not module.exists():
            found = sorted(p.name for p in (build_dir / "python").glob("implicitfit*.so"))
            raise RuntimeError("%s: no %s (built: %s); the build tree is for another Python than "
                               "%s" % (build_dir, module.name, ", ".join(found) or "nothing",
                                       sys.executable))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(module, target)
        shutil.copyfile(ROOT / "python" / "implicitfit.pyi", target.parent / "implicitfit.pyi")


OWN_BUILD.mkdir(exist_ok=True)
setup(
    version=project_version(),
    ext_modules=[Extension("implicitfit", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    packages=[],
    py_modules=[],
    options={"build": {"build_base": str(OWN_BUILD / "setuptools")},
             "egg_info": {"egg_base": str(OWN_BUILD)}},
    zip_safe=False,
)
