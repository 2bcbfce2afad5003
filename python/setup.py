"""Builds nck._nck with CMake (the repository's CMakeLists.txt, target
_nck) and puts it into the wheel; the version is CMake's project(VERSION).

Environment:
  NCK_SOURCE_DIR    the nck source tree (default: the folder above this one)
  NCK_CMAKE_BUILD   a CMake build folder to use (and reuse); default: one
                    under setuptools' build_temp, configured Release
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = pathlib.Path(os.environ.get("NCK_SOURCE_DIR", HERE.parent)).resolve()


def version():
    cmake = SOURCE / "CMakeLists.txt"
    if not cmake.is_file():
        sys.exit(f"nck: no nck source tree at {SOURCE} (set NCK_SOURCE_DIR)")
    return re.search(r"project\(nck VERSION ([0-9.]+)", cmake.read_text()).group(1)


class CMakeBuild(build_ext):
    """Configures the source tree without tests and benchmarks, builds only
    the module's target and copies the module where setuptools wants it."""

    def build_extension(self, ext):
        build = pathlib.Path(os.environ.get("NCK_CMAKE_BUILD") or pathlib.Path(self.build_temp).resolve() / "cmake")
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(SOURCE), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                            "-DNCK_BUILD_TESTS=OFF", "-DNCK_BUILD_BENCH=OFF", f"-DPython3_EXECUTABLE={sys.executable}"],
                           check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "_nck"], check=True)
        built = next((build / "python" / "nck").glob("_nck*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(version=version(), ext_modules=[Extension("nck._nck", sources=[])], cmdclass={"build_ext": CMakeBuild})
