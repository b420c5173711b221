"""Sphinx configuration of beamimpact's documentation (tools/build-docs.sh builds it).

Pages are the Markdown (MyST) files of docs/; the index's toctree takes every one of them by
glob, so a page added to docs/ is built without touching this file. The C++ API comes from
Doxygen's XML through Breathe (BEAMIMPACT_DOXYGEN_XML), the Python API from the docstrings of
the built package (PYTHONPATH=build/python; without it the compiled core is mocked).
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

root = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(root / "python"))  # the pure-Python package; the build's copy wins if on PYTHONPATH

project = "beamimpact"
author = "beamimpact contributors"
copyright = "beamimpact contributors"
_version = re.search(r"project\(beamimpact VERSION ([0-9.]+)", (root / "CMakeLists.txt").read_text())
release = version = _version.group(1) if _version else "0"

extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".md": "markdown"}
master_doc = "index"
exclude_patterns = ["_build", "_gallery", "**/README.md"]
html_theme = "furo"
html_title = f"beamimpact {release}"
html_static_path = []
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 4  # [text](page.md#a-heading) links resolve
# Pages written by different people start their sections at different depths.
suppress_warnings = ["myst.header"]



def _more_pages(app, docname, source):
    """Every docs/*.md page (by glob) that the index's first toctree does not list goes into its
    "More pages" toctree, so that a page added to docs/ needs no registration."""
    if docname != "index":
        return
    text = source[0]
    first = text.split("```{toctree}", 2)[1].split("```", 1)[0]
    listed = {line.strip() for line in first.splitlines() if line.strip() and not line.startswith(":")}
    more = sorted(p.stem for p in Path(app.srcdir).glob("*.md") if p.stem not in listed | {"index"})
    source[0] = text.replace("MORE_PAGES", "\n".join(more))


def _repository_path(app, env, node, contnode):
    """A Markdown link to a folder of the repository ([references/exact](../references/exact/))
    is no page: it is shown as its text instead of failing the build. A link to a path that does
    not exist still fails."""
    if node.get("reftype") not in ("myst", "any") or not node.get("refdoc"):
        return None  # MyST asks with reftype "any" before it warns
    target = (Path(env.doc2path(node["refdoc"])).parent / node["reftarget"].split("#")[0]).resolve()
    if target.is_dir() and (target == root or root in target.parents):
        return contnode
    return None


def _example_title(text, stem):
    """An example's title: the first line of its docstring, or its first Markdown heading."""
    m = re.match(r'\s*"""(.+)', text) or re.search(r"^# # (.+)$", text, re.M)
    return m.group(1).strip().rstrip(".") if m else stem


def _gallery(app, docname, source):
    """The gallery page: each examples/python/*.py run as a user runs it (the built module on
    PYTHONPATH, an empty working folder under docs/_gallery/), then its title, its figures and
    its code. An example that fails stops the build with its output."""
    if docname != "gallery":
        return
    parts = []
    for example in sorted((root / "examples/python").glob("*.py")):
        folder = Path(app.srcdir) / "_gallery" / example.stem
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
        done = subprocess.run([sys.executable, str(example)], cwd=folder, capture_output=True, text=True,
                              env={**os.environ, "MPLBACKEND": "Agg"})
        if done.returncode:
            raise RuntimeError(f"gallery: {example.name} failed:\n{done.stdout}\n{done.stderr}")
        text = example.read_text()
        parts.append(f"## {_example_title(text, example.stem)}\n\n`examples/python/{example.name}`\n")
        for png in sorted(folder.rglob("*.png")):
            parts.append(f"```{{image}} {png.relative_to(app.srcdir).as_posix()}\n:alt: {example.stem}\n```\n")
        parts.append(f"```{{literalinclude}} ../examples/python/{example.name}\n:language: python\n```\n")
    source[0] = source[0].replace("GALLERY", "\n".join(parts))


def setup(app):
    app.connect("source-read", _more_pages)
    app.connect("source-read", _gallery)
    app.connect("missing-reference", _repository_path)


# Python API: the built package when importable, else its compiled core mocked (docstrings of
# the pure-Python layer are what the page shows).
autodoc_mock_imports = []
try:
    import beamimpact._core  # noqa: F401
except ImportError:
    autodoc_mock_imports = ["beamimpact._core"]
autodoc_typehints = "description"
autodoc_member_order = "bysource"
nitpicky = True
nitpick_ignore_regex = [
    ("py:class", r"(numpy|np|os|pathlib|collections\.abc|typing)\..*"),
    ("py:class", r"(Path|PathLike|ndarray|Callable|Iterable|Mapping|Sequence|Any)"),
    ("py:class", r"beamimpact\._core\..*"),
    # The C++ page documents the public API; the types it names from other modules (Scene,
    # Vec2, ContactState, std::...) are not on it, and Breathe's links to Doxygen's file pages
    # (run_8hpp) have no target since no file page is generated.
    ("cpp:identifier", r".*"),
    ("std:ref", r".*_8hpp"),
]

# C++ API through Breathe, from the XML that tools/build-docs.sh has Doxygen write.
extensions.append("breathe")
breathe_projects = {"beamimpact": os.environ.get("BEAMIMPACT_DOXYGEN_XML", str(root / "build/docs/doxygen/xml"))}
breathe_default_project = "beamimpact"
breathe_domain_by_extension = {"hpp": "cpp"}
