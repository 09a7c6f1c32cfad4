"""Shared fixtures of the Python module's tests (registered in CTest by tests/python/CMakeLists.txt).

CTest sets IMPLICITFIT_PYTHON_DIR (the build tree's module, first on PYTHONPATH), IMPLICITFIT_CLI
(the command line built from the same sources) and IMPLICITFIT_SOURCE_DIR (bundled data). Run by
hand:  IMPLICITFIT_PYTHON_DIR=build/python IMPLICITFIT_CLI=build/apps/implicitfit \
       IMPLICITFIT_SOURCE_DIR=. PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
"""
import os
import subprocess
from pathlib import Path

import pytest

import implicitfit


def _required_env(name):
    value = os.environ.get(name)
    if not value:
        raise pytest.UsageError(f"{name} is not set (see tests/python/conftest.py)")
    return value


def pytest_configure(config):
    # The module under test must be the build tree's, not an installed copy.
    module_dir = Path(_required_env("IMPLICITFIT_PYTHON_DIR")).resolve()
    loaded = Path(implicitfit.__file__).resolve().parent
    if loaded != module_dir:
        raise pytest.UsageError(f"implicitfit was imported from {loaded}, not {module_dir}")


_skipped = []


def pytest_runtest_logreport(report):
    if report.skipped:
        _skipped.append(report.nodeid)


def pytest_sessionfinish(session, exitstatus):
    # Nothing may pass silently: no test collected, or a skipped test, fails the run.
    if session.testscollected == 0 or _skipped:
        session.exitstatus = 1


@pytest.fixture(scope="session")
def cli():
    return _required_env("IMPLICITFIT_CLI")


@pytest.fixture(scope="session")
def data_dir():
    return Path(_required_env("IMPLICITFIT_SOURCE_DIR")) / "datasets" / "data"


def run(*args):
    """Runs a command, returns (exit code, stdout, stderr). Under the sanitizers the interpreter
    has the shared ASan runtime preloaded (tests/python/CMakeLists.txt); the command line carries
    its own static one, so the preload is not passed on to it (the two refuse to mix)."""
    env = {k: v for k, v in os.environ.items() if k != "LD_PRELOAD"}
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600,
                       env=env)
    return r.returncode, r.stdout, r.stderr


def spins_during(call):
    """How often this thread gets to run while another thread runs call(). With a 1 s switch
    interval the interpreter does not take the GIL from the other thread in the microseconds
    between setting the flag and entering the library (nor inside it, as C++ code): this thread
    runs during the call only if the call releases the GIL. Holding the GIL for the whole call
    leaves 0 (the flag is False again before this thread gets the GIL back); a released GIL lets
    it spin for the whole call."""
    import sys
    import threading
    state = {"in_call": False, "seen": 0}

    def work():
        state["in_call"] = True
        call()
        state["in_call"] = False

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1.0)
    try:
        thread = threading.Thread(target=work)
        thread.start()
        while thread.is_alive():
            if state["in_call"]:
                state["seen"] += 1
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    return state["seen"]


def write_model(path, root):
    import json
    path.write_text(json.dumps({"format": "implicitfit-model", "version": 1, "root": root}))
    return path
