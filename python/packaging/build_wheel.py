"""Packs the momenta package the CMake build assembled into a wheel, without compiling anything.

Usage: build_wheel.py PACKAGE_DIR VERSION LICENSE_FILE NOTICES_FILE OUT_DIR

PACKAGE_DIR is <build>/python/momenta (the compiled momenta._core beside the pure-Python files).
The wheel is made by pip and setuptools (Debian's, no index reached) from a staging folder that
holds a copy of the package and the metadata below, and lands in OUT_DIR as the only
momenta-*.whl there. Installing it (scripts/install-python.sh, tests/python/check_pip_install.sh)
copies files: the library is compiled once, by the build that made PACKAGE_DIR.
"""

import pathlib
import shutil
import subprocess
import sys
import tempfile

PYPROJECT = """\
[build-system]
requires = ["setuptools>=61", "wheel"]
build-backend = "setuptools.build_meta"

[project]
name = "momenta"
version = "{version}"
description = "Model, simulate and analyse mechanical systems from first principles"
requires-python = "=={major}.{minor}.*"
dependencies = ["numpy"]
license = {{text = "MIT (the module as built links GiNaC and CLN: GPL-2.0-or-later, see THIRD-PARTY-NOTICES)"}}

[project.optional-dependencies]
pandas = ["pandas"]

[tool.setuptools]
packages = ["momenta"]
license-files = ["LICENSE", "THIRD-PARTY-NOTICES.md"]

[tool.setuptools.package-data]
momenta = ["*.so", "*.pyi", "py.typed"]
"""

# The compiled module inside makes it a platform wheel (cp311-cp311-linux_x86_64), not py3-none-any.
SETUP = """\
from setuptools import setup
from setuptools.dist import Distribution


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True


setup(distclass=BinaryDistribution)
"""


def main(package_dir, version, license_file, notices_file, out_dir):
    package_dir, out_dir = pathlib.Path(package_dir), pathlib.Path(out_dir)
    if not any(package_dir.glob("_core*.so")):
        sys.exit(f"build_wheel.py: no compiled module (_core*.so) in {package_dir}")
    with tempfile.TemporaryDirectory(prefix="momenta-wheel-") as staging:
        staging = pathlib.Path(staging)
        shutil.copytree(package_dir, staging / "momenta",
                        ignore=shutil.ignore_patterns("__pycache__"))
        shutil.copy2(license_file, staging / "LICENSE")
        shutil.copy2(notices_file, staging / "THIRD-PARTY-NOTICES.md")
        (staging / "pyproject.toml").write_text(PYPROJECT.format(
            version=version, major=sys.version_info.major, minor=sys.version_info.minor))
        (staging / "setup.py").write_text(SETUP)
        wheels = staging / "dist"
        subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-index",
                        "--no-deps", "--no-build-isolation", "--wheel-dir", str(wheels),
                        str(staging)], check=True, cwd=staging)
        made = list(wheels.glob("momenta-*.whl"))
        if len(made) != 1:
            sys.exit(f"build_wheel.py: expected one wheel, pip made {made}")
        out_dir.mkdir(parents=True, exist_ok=True)
        for old in out_dir.glob("momenta-*.whl"):
            old.unlink()
        shutil.copy2(made[0], out_dir / made[0].name)
        print(f"momenta wheel: {out_dir / made[0].name}")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*sys.argv[1:])
