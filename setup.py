"""Builds the mdr wheel with the project's CMake build (pyproject.toml says why setuptools).

The wheel holds the `mdr` package (python/mdr/*.py and the compiled `_mdr` extension) and the real C++ command line
as the data file bin/mdr, which pip installs as <venv>/bin/mdr.

Environment:
  MDR_CMAKE_BUILD_DIR  an already configured CMake build directory of this source tree (e.g. `build` after
                       `make build`): its targets `_mdr` and `mdr` are brought up to date and used, nothing is
                       configured. Its Python must be the one that installs (the extension's file name says which).
                       Without it, a fresh Release build is configured under build/setuptools/cmake.
  CMAKE_BUILD_PARALLEL_LEVEL  jobs for the build (default: the number of cores).
"""

from __future__ import annotations

import glob
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
SETUPTOOLS_DIR = os.path.join("build", "setuptools")  # relative: setuptools wants relative paths for data files
STAGED_BINARY = os.path.join(SETUPTOOLS_DIR, "bin", "mdr")


def project_version() -> str:
    with open(os.path.join(HERE, "CMakeLists.txt"), encoding="utf-8") as handle:
        match = re.search(r"project\(mdr VERSION ([0-9.]+)", handle.read())
    if not match:
        raise RuntimeError("CMakeLists.txt: no `project(mdr VERSION x.y.z)`")
    return match.group(1)


# egg_info and build write here, not into the source tree (egg_info wants the folder to exist).
os.makedirs(os.path.join(HERE, SETUPTOOLS_DIR), exist_ok=True)


class CMakeBuild(build_ext):
    """Builds the targets `_mdr` and `mdr` with CMake instead of compiling sources itself."""

    def run(self) -> None:
        build_dir = os.environ.get("MDR_CMAKE_BUILD_DIR")
        if build_dir:
            build_dir = os.path.abspath(build_dir)
            if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
                raise RuntimeError(f"MDR_CMAKE_BUILD_DIR = {build_dir}: not a configured CMake build directory")
        else:
            build_dir = os.path.join(HERE, SETUPTOOLS_DIR, "cmake")
            subprocess.run(["cmake", "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                            "-DMDR_BUILD_TESTS=OFF", "-DMDR_BUILD_BENCH=OFF", "-DMDR_BUILD_PYTHON=ON",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build_dir, "--target", "_mdr", "mdr", "-j", jobs], check=True)

        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        extension = os.path.join(build_dir, "python", "mdr", "_mdr" + suffix)
        if not os.path.isfile(extension):
            built = glob.glob(os.path.join(build_dir, "python", "mdr", "_mdr*"))
            raise RuntimeError(f"{build_dir}: no _mdr{suffix} for this Python ({sys.executable}); built: {built}")
        target = self.get_ext_fullpath("mdr._mdr")
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(extension, target)

        # bin/mdr is a data file (setup() below): the binary is staged where that entry points.
        staged = os.path.join(HERE, STAGED_BINARY)
        os.makedirs(os.path.dirname(staged), exist_ok=True)
        shutil.copy2(os.path.join(build_dir, "bin", "mdr"), staged)


setup(
    version=project_version(),
    packages=["mdr"],
    package_dir={"": "python"},
    package_data={"mdr": ["*.pyi"]},
    ext_modules=[Extension("mdr._mdr", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # The command line is the C++ binary itself, not a Python wrapper: pip installs it as <prefix>/bin/mdr.
    data_files=[("bin", [STAGED_BINARY])],
    options={"build": {"build_base": SETUPTOOLS_DIR}, "egg_info": {"egg_base": SETUPTOOLS_DIR}},
    zip_safe=False,
)
