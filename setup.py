"""`pip install .` for the Python module: setuptools drives CMake, which builds the module
against the system's libraries (Debian's pybind11, oneTBB, OpenMesh, ...). Nothing is
downloaded: with no pyproject.toml, pip builds in this environment, without an isolated one.

    python3 -m venv --system-site-packages /tmp/venv && /tmp/venv/bin/pip install .
    sudo pip install --break-system-packages .      # or system-wide

See docs/python.md.
"""

import os
import re
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        target = Path(self.get_ext_fullpath(ext.name)).resolve()
        build = ROOT / "build-python"
        jobs = str(os.cpu_count() or 1)
        subprocess.check_call([
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            "-DPAPERCRAFT_BUILD_TESTS=OFF", "-DPAPERCRAFT_BUILD_BENCH=OFF",
            f"-DPython_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(build), "-j", jobs, "--target", "_papercraft"])
        built = next((build / "python" / "papercraft").glob("_papercraft*.so"))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))


version = re.search(r"project\(papercraft VERSION ([0-9.]+)",
                    (ROOT / "CMakeLists.txt").read_text()).group(1)
setup(
    name="papercraft",
    version=version,
    description="Paper patterns from triangle meshes, certified to a tolerance",
    packages=["papercraft"],
    package_dir={"": "python"},
    ext_modules=[CMakeExtension("papercraft._papercraft")],
    cmdclass={"build_ext": CMakeBuild},
    install_requires=["numpy"],
    python_requires=">=3.9",
    zip_safe=False,
)
