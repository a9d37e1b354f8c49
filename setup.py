"""The extension rotlie._rotlie built by CMake for `pip install .` (the metadata is in pyproject.toml).

CMake configures the whole project (the extension links the library floor, which needs GiNaC and
CLN) with Python_EXECUTABLE set to the interpreter pip runs, builds only the target rotlie_python,
and the built module is copied where setuptools packs it.

ROTLIE_CMAKE_BUILD_DIR names a build tree of this source already configured for the same interpreter
(e.g. build/release, which finds /usr/bin/python3): the module is brought up to date there instead of
compiling the libraries a second time.
"""
import importlib.machinery
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("ROTLIE_CMAKE_BUILD_DIR")
        if given:
            build_dir = pathlib.Path(given).resolve()
            if not (build_dir / "CMakeCache.txt").is_file():
                raise RuntimeError(f"ROTLIE_CMAKE_BUILD_DIR={given} is not a configured CMake build tree")
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython_EXECUTABLE={sys.executable}", "-DROTLIE_BUILD_PYTHON=ON",
                            "-DROTLIE_BUILD_TESTS=OFF", "-DROTLIE_BUILD_BENCH=OFF"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "rotlie_python", "-j", jobs], check=True)
        built = sorted((build_dir / "python" / "rotlie").glob("_rotlie*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one built module in {build_dir / 'python' / 'rotlie'}, found {built}")
        if not any(built[0].name.endswith(suffix) for suffix in importlib.machinery.EXTENSION_SUFFIXES):
            raise RuntimeError(f"{built[0].name} was built for another interpreter than {sys.executable}")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)


setup(ext_modules=[CMakeExtension("rotlie._rotlie")], cmdclass={"build_ext": CMakeBuild})
