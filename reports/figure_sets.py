"""@brief The committed figure sets of the report page: each set's manifest (figures.json) read and
checked, its PNGs copied beside the page (images as separate files, loaded lazily), and every figure
told apart as made by this run or by an older build (its version, that version's commit date and the
command that remakes it)."""
import datetime
import functools
import json
import os
import shutil
import subprocess

from report_files import write_json_atomic

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Each committed set, in report order, with the command that regenerates it
# (tools/run-verification.sh --figures runs the ones that need no hours).
FIGURE_SETS = {
    "work_precision": "/usr/bin/python3 reports/work_precision.py",
    "figures": "build/beamimpact study verification/studies/s4_angle_friction.toml --out DIR; "
               "/usr/bin/python3 reports/study_maps.py DIR --x alpha0 --y mu --facet mesh --norm impulse",
    "paper_figures": "/usr/bin/python3 reports/paper_figures.py",
    "scorecards": "build/beamimpact score NAME --out /tmp/scores/NAME for each method; "
                  "/usr/bin/python3 reports/scorecard_table.py /tmp/scores/* --set reports/scorecards",
    "classical_benchmarks": "/usr/bin/python3 reports/classical_benchmarks.py",
    "beam_theories": "/usr/bin/python3 reports/beam_theories.py",
    "benchmarks": "/usr/bin/python3 reports/plot_effects_benchmark.py --run",
    "setup": "/usr/bin/python3 reports/plot_setup_benchmark.py --run",
}
FIGURE_KEYS = ("png", "title", "command", "scene", "version")


def made_now():
    """@brief The time a figure is made, UTC, "2026-11-29T08:00:00Z" (a manifest's "made")."""
    return datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


def manifest_figure(png, title, command, scene, version, caption, made=None):
    """@brief One figure of a manifest: how it was made (command, scene, version, the date) and its
    caption, said here once and shown under the image; nothing of it is drawn into the image.
    @param png the image's path relative to the manifest
    @param title the figure's heading
    @param command the command that remakes it, from the repository root
    @param scene the scene file(s) its data comes from
    @param version the beamimpact version that made its data ("0.1.0+abc1234")
    @param caption what the figure shows and whatever else a reader needs (units, what is left out)
    @param made the time it was made (default: now, UTC)"""
    return {"png": png, "title": title, "command": command, "scene": scene, "version": version,
            "made": made or made_now(), "caption": caption}


def write_manifest(path, title, figures, about="", tables=()):
    """@brief Writes a figure set's manifest (figures.json, or PREFIX_figures.json), atomically: the
    one format the report page reads (figure_set below).
    @param figures manifest_figure() entries
    @param tables [{"title", "columns", "rows"}] shown above the figures"""
    for f in figures:
        missing = [k for k in FIGURE_KEYS + ("made", "caption") if k not in f]
        if missing:
            raise ValueError(f"{path}: figure {f.get('png', '?')} lacks {', '.join(missing)} (use manifest_figure)")
    doc = {"title": title, "about": about, "tables": list(tables), "figures": list(figures)}
    write_json_atomic(path, doc)
    return doc


class InputProblem(Exception):
    """A manifest or a figure the page cannot be made from (the caller exits 2 with it)."""


def load_json(path, what):
    """@brief The JSON document at `path`. @param what what the file is, for the message."""
    try:
        with open(path) as f:
            return json.load(f)
    except FileNotFoundError:
        raise InputProblem(f"{path}: not found ({what})") from None
    except json.JSONDecodeError as e:
        raise InputProblem(f"{path}: not valid JSON ({e})") from None


@functools.lru_cache(maxsize=None)
def version_date(version):
    """@brief The commit date (YYYY-MM-DD) of a version "0.1.0+abc1234", from this checkout's git
    history; "" when the commit is not in it (a shallow clone, a fixture)."""
    commit = version.split("+", 1)[1] if "+" in version else ""
    if not commit:
        return ""
    try:
        r = subprocess.run(["git", "-C", REPO, "show", "-s", "--format=%cs", commit + "^{commit}"],
                           capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.TimeoutExpired):
        return ""
    return r.stdout.strip() if r.returncode == 0 else ""


def figure_entry(set_dir, name, fig, run_version, out_dir):
    """@brief One figure of a set, its PNG copied to OUT_DIR/figures/NAME/ (path relative to the page)."""
    for k in FIGURE_KEYS:
        if k not in fig:
            raise InputProblem(f"{set_dir}/figures.json: a figure lacks '{k}' "
                               f"(each figure needs {', '.join(FIGURE_KEYS)})")
    src = os.path.join(set_dir, fig["png"])
    if not os.path.isfile(src):
        raise InputProblem(f"{set_dir}/figures.json: figure '{fig['png']}' not found")
    rel = os.path.join("figures", name, fig["png"])
    dst = os.path.join(out_dir, rel)
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    shutil.copyfile(src, dst)
    return {**fig, "src": rel, "anchor": f"fig-{name}-{os.path.splitext(fig['png'])[0]}".replace("/", "-"),
            "this_run": fig["version"] == run_version, "date": version_date(fig["version"]),
            "bytes": os.path.getsize(src)}


def figure_set(set_dir, run_version, out_dir):
    """@brief A set's manifest with its figures placed beside the page, or, when the set has no
    manifest in this checkout, {"missing": True} with the command that makes it."""
    name = os.path.basename(os.path.normpath(set_dir))
    manifest = os.path.join(set_dir, "figures.json")
    if not os.path.exists(manifest):
        return {"name": name, "title": name, "missing": True, "command": FIGURE_SETS.get(name, "its generator")}
    m = load_json(manifest, "a figure set's manifest")
    for k in ("title", "figures"):
        if k not in m:
            raise InputProblem(f"{manifest}: key '{k}' missing")
    figs = [figure_entry(set_dir, name, f, run_version, out_dir) for f in m["figures"]]
    return {"name": name, "title": m["title"], "about": m.get("about", ""), "tables": m.get("tables", []),
            "figures": figs, "missing": False, "command": FIGURE_SETS.get(name, "its generator")}


def provenance(sets, run_version):
    """@brief How many figures this run made, and the older builds the others come from
    ([(version, date, count)], oldest date first)."""
    figs = [f for s in sets for f in s.get("figures", [])]
    older = {}
    for f in figs:
        if not f["this_run"]:
            older[f["version"]] = older.get(f["version"], 0) + 1
    rows = sorted(((v, version_date(v), n) for v, n in older.items()), key=lambda r: (r[1] or "9", r[0]))
    return {"figures": len(figs), "this_run": sum(f["this_run"] for f in figs), "older": rows,
            "versions": len(older) + 1, "run_version": run_version}
