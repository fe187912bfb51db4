"""Builds the momenta Python package with the project's own CMake build (docs/python.md).

pip calls this through pyproject.toml: `python3 -m pip install --no-build-isolation .` configures
CMake with the running interpreter, builds the `momenta_python` target (the libraries it needs,
not the tests, benchmarks or command line) and packs build/python/momenta.
"""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
        env = dict(os.environ)
        env.setdefault("CCACHE_DIR", str(pathlib.Path.home() / ".cache" / "momenta" / "ccache"))
        env.setdefault("CCACHE_BASEDIR", str(ROOT))
        env.setdefault("CCACHE_NOHASHDIR", "1")
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", f"-DPython3_EXECUTABLE={sys.executable}",
                        "-DMOMENTA_BUILD_TESTS=OFF", "-DMOMENTA_BUILD_BENCHMARKS=OFF",
                        "-DMOMENTA_BUILD_APPS=OFF", "-DMOMENTA_BUILD_PYTHON=ON"],
                       check=True, env=env)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "momenta_python",
                        "--parallel", str(os.cpu_count() or 2)], check=True, env=env)
        package = build_dir / "python" / "momenta"
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).parent
        target.mkdir(parents=True, exist_ok=True)
        for file in package.iterdir():
            shutil.copy2(file, target / file.name)


setup(
    packages=["momenta"],
    package_dir={"": "python"},
    package_data={"momenta": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("momenta._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
