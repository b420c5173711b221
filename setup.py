"""The Python package's build for pip (pyproject.toml): the pure-Python files of python/beamimpact
plus the compiled core beamimpact._core, built by CMake (target beamimpact_python) in
BEAMIMPACT_BUILD_DIR (default build/, configured when it is not yet) and copied into the wheel."""
import os
import re
import subprocess
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("BEAMIMPACT_BUILD_DIR", "build"))
BUILD = BUILD if BUILD.is_absolute() else ROOT / BUILD


def version():
    """The project's version, from CMakeLists.txt's project() (one place)."""
    return re.search(r"project\(beamimpact VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class BuildWithCMake(build_ext):
    """Builds beamimpact._core with the project's CMake build instead of compiling sources here."""

    def build_extension(self, ext):
        if not (BUILD / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release"], check=True)
        jobs = os.environ.get("BEAMIMPACT_JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(BUILD), "--target", "beamimpact_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = BUILD / "python" / "beamimpact" / f"_core{suffix}"
        if not built.exists():
            raise RuntimeError(f"{built} was not built: the CMake build's Python ({BUILD}/CMakeCache.txt, "
                               f"Python_EXECUTABLE) differs from this one ({suffix}), or pybind11-dev is missing")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))


(BUILD / "pip").mkdir(parents=True, exist_ok=True)
setup(
    version=version(),
    ext_modules=[Extension("beamimpact._core", sources=[])],
    cmdclass={"build_ext": BuildWithCMake},
    options={"build": {"build_base": str(BUILD / "pip")}, "egg_info": {"egg_base": str(BUILD / "pip")}},
)
