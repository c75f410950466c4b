"""Builds the extension dcel._dcel with CMake for pip (pyproject.toml has the
rest). The CMake build is the project's own: the library, the generators and
python/src, in Release, nothing else (no tests, no CLI), into build-python/
(next to the developers' build/ directories, and ignored by git like them).
CMAKE_BUILD_PARALLEL_LEVEL sets the jobs (default 2), CMAKE_BUILD_TYPE the
build type (default Release); a ccache found on PATH is used."""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        out_dir = os.path.dirname(os.path.abspath(self.get_ext_fullpath(ext.name)))
        build_dir = os.path.join(ROOT, "build-python", "cmake")
        configure = [
            "cmake", "-S", ROOT, "-B", build_dir,
            "-DCMAKE_BUILD_TYPE=" + (os.environ.get("CMAKE_BUILD_TYPE") or "Release"),
            "-DDCEL_DEVELOPER_MODE=OFF",
            "-DDCEL_BUILD_CLI=OFF",
            "-DDCEL_BUILD_PYTHON=ON",
            f"-DPython3_EXECUTABLE={sys.executable}",
            f"-DDCEL_PYTHON_OUTPUT_DIR={out_dir}",
        ]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        env = dict(os.environ)
        env.setdefault("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(configure, check=True, env=env)
        subprocess.run(["cmake", "--build", build_dir, "--target", "dcel_python"], check=True, env=env)


setup(
    ext_modules=[Extension("dcel._dcel", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join("build-python", "setuptools")}},
)
