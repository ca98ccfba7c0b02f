"""Builds the Python module apollonius3d with the project's CMake, for `pip install --no-build-isolation .`.

The module is the CMake target apollonius3d_python (python/CMakeLists.txt), built for the interpreter
that runs pip. By default in build-python/ (the library's layers and the module only, no tests); with
APOLLONIUS3D_CMAKE_BUILD_DIR in an existing CMake build, such as scripts/build.sh's build/, which must
then be configured for this interpreter. CMAKE_BUILD_PARALLEL_LEVEL sets the build jobs (default 2).
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


def project_version():
    """The version of CMakeLists.txt's project(), the one source of it."""
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(apollonius3d VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        given = os.environ.get("APOLLONIUS3D_CMAKE_BUILD_DIR")
        build = Path(given).resolve() if given else SOURCE / "build-python"
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        if not given:
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                            "-DAPOLLONIUS_TESTS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        elif not (build / "CMakeCache.txt").exists():
            raise RuntimeError(f"APOLLONIUS3D_CMAKE_BUILD_DIR={given} is not a configured CMake build")
        subprocess.run(["cmake", "--build", str(build), "--target", "apollonius3d_python", "-j", jobs], check=True)
        built = build / "python" / Path(self.get_ext_filename(ext.name)).name
        if not built.exists():
            raise RuntimeError(f"no {built}: is {build} configured for {sys.executable}? (python/CMakeLists.txt "
                               "prints the interpreter it found)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    ext_modules=[CMakeExtension("apollonius3d")],
    cmdclass={"build_ext": CMakeBuild},
    packages=[],
    py_modules=[],
    options={"build": {"build_base": "build-python/setuptools"}},
    zip_safe=False,
)
