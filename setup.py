"""The build of `pip install .` (pyproject.toml): setuptools runs the project's CMake build for
the one target fdhcert_python and packs the module it makes, with its type stubs
(python/stubs/fdhcert-stubs). docs/python.md says why setuptools and not meson-python.

FDHCERT_CMAKE_BUILD_DIR=DIR reuses an existing, configured CMake build folder (as ./run build
makes it): only fdhcert_python is brought up to date there, and setuptools' own files go to
DIR/pip. Without it the build is from scratch, in build-pip/ of the source folder (kept, so a
second `pip install .` is incremental)."""
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
REUSE = os.environ.get("FDHCERT_CMAKE_BUILD_DIR")
WORK = Path(REUSE).resolve() / "pip" if REUSE else ROOT / "build-pip"


def version():
    """The one version: CMakeLists.txt's project(fdhcert VERSION x.y.z)."""
    found = re.search(r"project\(fdhcert VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not found:
        sys.exit("setup.py: no project(fdhcert VERSION ...) in CMakeLists.txt")
    return found.group(1)


def cmake(*args):
    print("setup.py: cmake", *args, flush=True)
    subprocess.run(["cmake", *map(str, args)], check=True)


class CMakeBuild(build_ext):
    """Builds the extension fdhcert with CMake instead of setuptools' compiler."""

    def build_extension(self, ext):
        if REUSE:
            build = Path(REUSE).resolve()
            if not (build / "CMakeCache.txt").is_file():
                sys.exit(f"setup.py: FDHCERT_CMAKE_BUILD_DIR={REUSE} is no configured CMake "
                         "build folder (./run build makes one)")
        else:
            build = WORK / "cmake"
            generator = ["-G", "Ninja"] if shutil.which("ninja") and \
                not (build / "CMakeCache.txt").exists() else []
            # The module's parts only: no tests, no peer libraries; for this interpreter.
            cmake("-S", ROOT, "-B", build, *generator, "-DCMAKE_BUILD_TYPE=Release",
                  "-DBUILD_TESTING=OFF", "-DFDH_WITH_PEERS=OFF",
                  f"-DPython_EXECUTABLE={sys.executable}")
        cmake("--build", build, "--target", "fdhcert_python")
        built = build / "python" / ("fdhcert" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            sys.exit(f"setup.py: {built} was not built (a build folder for another Python?)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


WORK.mkdir(parents=True, exist_ok=True)
setup(
    version=version(),
    ext_modules=[Extension("fdhcert", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    packages=["fdhcert-stubs"],
    package_dir={"fdhcert-stubs": "python/stubs/fdhcert-stubs"},
    package_data={"fdhcert-stubs": ["__init__.pyi", "py.typed"]},
    # setuptools' own folders away from the CMake build folder build/ and the source.
    options={"build": {"build_base": str(WORK / "setuptools")},
             "egg_info": {"egg_base": str(WORK)}},
    zip_safe=False,
)
