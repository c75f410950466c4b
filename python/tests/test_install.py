"""The documented install (docs/python.md) in a fresh virtual environment:
pip builds the extension from the source tree, offline, and the installed
package runs the docs' pytest example. The build is a Debug one
(CMAKE_BUILD_TYPE, which setup.py reads): what is tested is the install, not
the optimizer, and -O0 compiles the library in about half the time of the
Release build a user gets. Slow the first time (the library in
build-python/), incremental afterwards."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR


def test_pip_install_from_the_source_tree(tmp_path):
    venv = tmp_path / "venv"
    python = str(venv / "bin" / "python")
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], check=True)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONDONTWRITEBYTECODE")}
    env["CMAKE_BUILD_TYPE"] = "Debug"
    done = subprocess.run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "."],
                          cwd=SOURCE_DIR, env=env, capture_output=True, text=True, timeout=3000)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    where = subprocess.run([python, "-c", "import dcel; print(dcel.__file__)"], cwd=str(tmp_path), env=env,
                           capture_output=True, text=True, check=True).stdout
    assert str(venv) in where  # the installed copy, not the source tree
    done = subprocess.run([python, "-m", "pytest", "-q", "-p", "no:cacheprovider", "examples/python/test_pure_dcel.py"],
                          cwd=SOURCE_DIR, env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0 and "3 passed" in done.stdout, done.stdout + done.stderr
