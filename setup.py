"""The Python package's build for pip (pyproject.toml): a complete install of beamimpact.

- the pure-Python files of python/beamimpact plus the compiled core beamimpact._core;
- the `beamimpact` program, into the environment's bin/ (a data file of the wheel's "bin" scheme
  path: the compiled program itself, no Python wrapper in front of it);
- the shipped data into the environment's share/beamimpact/: verification/scenes/**,
  verification/matrix.toml, verification/methods.toml and verification/cards.toml, and the adapters methods.toml points
  to by `{here}/../` (references/<name>/*.py, examples/external_solver/penalty_central.py), and
  the page generator that `beamimpact score` and `conform` run (reports/page_files.txt and
  reports/templates/*.j2, into share/beamimpact/reports/).

This is the layout `cmake --install` makes (cmake/package.cmake): the program finds its data
from its own location (bin/ -> ../share/beamimpact, api/methods_file.cc data_root()) and the
module finds the program and the data from its own (site-packages/beamimpact -> ../../../bin,
../../../share/beamimpact), so nothing needs an environment variable, from any folder.

The program and the core are built by CMake (targets beamimpact and beamimpact_python) in
BEAMIMPACT_BUILD_DIR (default build/, configured when it is not yet): about 12 minutes on 2 cores
from nothing, seconds when build/ is built. pip hides a build's output unless -v: the progress
lines of CMake ([ 57%] Building ...) are also written to the terminal (/dev/tty) when there is one.
"""
import os
import re
import subprocess
import sys
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


def _terminal():
    """The user's terminal, when pip runs in one (pip captures stdout and stderr), else None."""
    try:
        return open("/dev/tty", "w")
    except OSError:
        return None


def _cmake(args, tty):
    """Runs cmake, its output streamed to stdout (shown by pip -v) and its progress lines to tty."""
    with subprocess.Popen(["cmake", *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True) as p:
        for line in p.stdout:
            sys.stdout.write(line)
            if tty and (line.startswith("[") or line.startswith("-- Configuring") or "error" in line):
                tty.write("beamimpact build: " + line)
                tty.flush()
    if p.returncode:
        raise subprocess.CalledProcessError(p.returncode, ["cmake", *args])


class BuildWithCMake(build_ext):
    """Builds beamimpact._core and the beamimpact program with the project's CMake build."""

    def build_extension(self, ext):
        tty = _terminal()
        if tty:
            tty.write(f"beamimpact build: CMake in {BUILD} (about 12 min on 2 cores from nothing; "
                      "pip -v shows the whole output)\n")
        if not (BUILD / "CMakeCache.txt").exists():
            _cmake(["-S", str(ROOT), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release"], tty)
        jobs = os.environ.get("BEAMIMPACT_JOBS", str(os.cpu_count() or 1))
        _cmake(["--build", str(BUILD), "--target", "beamimpact_python", "beamimpact", "-j", jobs], tty)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = BUILD / "python" / "beamimpact" / f"_core{suffix}"
        if not built.exists():
            raise RuntimeError(f"{built} was not built: the CMake build's Python ({BUILD}/CMakeCache.txt, "
                               f"Python_EXECUTABLE) differs from this one ({suffix}), or pybind11-dev is missing")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))


def _files(folder, pattern, exclude=("tests",)):
    """(install folder, [files]) pairs of ROOT/folder's files matching pattern, one per folder."""
    groups = {}
    for f in sorted((ROOT / folder).rglob(pattern)):
        rel = f.relative_to(ROOT)
        if f.is_file() and not set(rel.parts) & {*exclude, "__pycache__"}:
            groups.setdefault(str(Path("share/beamimpact") / rel.parent), []).append(str(rel))
    return list(groups.items())


def data_files():
    """The program and the shipped data, in cmake --install's layout (see the module's comment);
    the references methods.toml points to (getfem and any other with a run.py as well)."""
    out = [("bin", [os.path.relpath(BUILD / "beamimpact", ROOT)])]  # setup() takes relative paths only
    out += _files("verification/scenes", "*.toml")
    out += [("share/beamimpact/verification", ["verification/matrix.toml", "verification/methods.toml",
                                                       "verification/cards.toml"])]
    for ref in sorted(p.parent.name for p in (ROOT / "references").glob("*/run.py")):
        out += _files(f"references/{ref}", "*.py")
    out += _files("references/common", "*.py")  # what the Python references share (contact intervals)
    out += [("share/beamimpact/examples/external_solver", ["examples/external_solver/penalty_central.py"])]
    # The page generator that score and conform run (reports/page_files.txt, as cmake --install ships it).
    pages = [line.strip() for line in (ROOT / "reports/page_files.txt").read_text().splitlines()
             if line.strip() and not line.startswith("#")]
    out += [("share/beamimpact/reports", [f"reports/{f}" for f in pages])]
    out += _files("reports/templates", "*.j2")
    return out


(BUILD / "pip").mkdir(parents=True, exist_ok=True)
setup(
    version=version(),
    ext_modules=[Extension("beamimpact._core", sources=[])],
    data_files=data_files(),
    cmdclass={"build_ext": BuildWithCMake},
    options={"build": {"build_base": str(BUILD / "pip")}, "egg_info": {"egg_base": str(BUILD / "pip")}},
)
