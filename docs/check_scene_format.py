#!/usr/bin/python3
"""Checks that docs/scene-format.md documents the scene format and the outputs that the code has.

  /usr/bin/python3 docs/check_scene_format.py --keys build/docs/scene_format_keys --page docs/scene-format.md --root .

What the code has comes from the code itself: the program docs/scene_format_keys.cc lists the keys
the scene reader and the in-process methods' option readers ask about, the history.csv columns of
the output schema and the keys of the summary.json of a run of each method; the FEniCSx reference's
[fenicsx] keys are the ones its reader (references/fenicsx/options.py) names when it refuses an
unknown key.

What the page documents is read by these rules:
- a key table is a Markdown table whose header's first cell is "key"; each row documents the key
  that is the first `code` span of its first cell;
- in the part "The scene file", a key table belongs to the TOML table named by the first `code`
  span in brackets of the heading above it (`[time]`, `[[bodies]]`, `[[bodies.supports]]`; none:
  the top level), and such a heading documents that table itself;
- in the part "The outputs of a run", the table whose header's first cell is "column" lists the
  history.csv columns (every `code` span of a first cell), and a key table belongs to the
  summary.json object named by the first `code` span of the heading above it (`summary.json`: the
  top level; `contacts[]`: an entry of "contacts").

Fails (exit 1), naming each, for: a key the readers accept that the page does not document, a key
the page documents that no reader accepts, a history column missing from the page or not in the
schema, a code of column `state` not given as "CODE NAME" in its row, a summary.json key of a run
missing from the page. Keys of summary.json that a run writes only in some cases (warnings, a note)
may be documented without a run here writing them.
"""

import argparse
import json
import re
import subprocess
import sys
import types
from pathlib import Path

SCENE_PART = "The scene file"
OUTPUT_PART = "The outputs of a run"
# summary.json objects whose keys are data, not names of the format: body names, scene key paths,
# the resolved scene tables (their keys are the scene's, checked with the scene), and the methods'
# own objects (documented with each method).
SUMMARY_DATA_OBJECTS = {"bodies", "assumed", "overrides", "settings", "exact", "ida", "warnings"}


def code_spans(text):
    return re.findall(r"`([^`]+)`", text)


def table_cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def read_page(path):
    """The page's documentation: {"scene": {key}, "tables": {table}, "history": {column},
    "state_row": text, "summary": {object: {key}}}."""
    doc = {"scene": set(), "tables": set(), "history": set(), "state_row": "", "summary": {}}
    part, owner, header = None, "", None
    for line in Path(path).read_text().splitlines():
        if line.startswith("#"):
            title = line.lstrip("#").strip()
            if line.startswith("## "):
                part = "scene" if title == SCENE_PART else "outputs" if title == OUTPUT_PART else None
            spans = code_spans(title)
            if part == "scene":
                tables = [s for s in spans if s.startswith("[")]
                owner = tables[0].strip("[]") if tables else ""
                if owner:
                    doc["tables"].add(owner)
            elif part == "outputs":
                owner = spans[0] if spans else None
                owner = "" if owner == "summary.json" else owner.rstrip("[]") if owner else None
            header = None
            continue
        if not line.startswith("|"):
            header = None
            continue
        cells = table_cells(line)
        if header is None:
            header = cells[0].lower()
            continue
        if set(cells[0]) <= set("-: "):
            continue
        spans = code_spans(cells[0])
        if not spans:
            continue
        if part == "scene" and header == "key":
            doc["scene"].add(f"{owner}.{spans[0]}" if owner else spans[0])
        elif part == "outputs" and header == "column":
            doc["history"].update(spans)
            if "state" in spans:
                doc["state_row"] = line
        elif part == "outputs" and header == "key" and owner is not None:
            doc["summary"].setdefault(owner, set()).add(spans[0])
    return doc


def fenicsx_keys(root):
    """The [fenicsx] keys, as the FEniCSx reference's option reader names them for an unknown key."""
    sys.path.insert(0, str(Path(root) / "references" / "fenicsx"))
    import options  # noqa: E402 (the reference's own module)
    from scene import InputError  # noqa: E402
    scene = types.SimpleNamespace(file="<check>", fenicsx={"?": 1}, bodies=[], dt=0.01, output_every=1)
    try:
        options.resolve_options(scene, {})
    except InputError as e:
        listed = str(e).split("expected one of ", 1)
        if len(listed) == 2:
            return {"fenicsx"} | {"fenicsx." + k.strip() for k in listed[1].split(",")}
    raise SystemExit("check_scene_format: the [fenicsx] reader did not list its keys for an unknown key")


def check(code, doc):
    """The list of discrepancies between the code's lists and the page."""
    errors = []
    accepted = code["scene_keys"]
    tables = {k for k in accepted if any(o.startswith(k + ".") for o in accepted)}
    for key in sorted(accepted):
        if key not in doc["scene"] and key not in doc["tables"]:
            errors.append(f"scene key '{key}' is accepted by the reader but not documented")
    for key in sorted(doc["scene"] - accepted):
        errors.append(f"scene key '{key}' is documented but no reader accepts it")
    for table in sorted(doc["tables"] - tables):
        errors.append(f"table '[{table}]' is documented but the scene has no such table")
    columns = set(code["history"]["columns"])
    for c in sorted(columns - doc["history"]):
        errors.append(f"history.csv column '{c}' is written but not documented")
    for c in sorted(doc["history"] - columns):
        errors.append(f"history.csv column '{c}' is documented but not in the output schema")
    for value, name in code["history"]["state_values"].items():
        if f"{value} {name}" not in doc["state_row"]:
            errors.append(f"column 'state': code '{value} {name}' is not in its row")
    for obj, keys in sorted(code["summary"].items()):
        if obj in SUMMARY_DATA_OBJECTS:
            continue
        where = "summary.json" + (f" '{obj}'" if obj else "")
        for key in sorted(set(keys) - doc["summary"].get(obj, set())):
            errors.append(f"{where} key '{key}' is written by a run but not documented")
    return errors


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--keys", required=True, help="the scene_format_keys program")
    ap.add_argument("--page", required=True, help="docs/scene-format.md")
    ap.add_argument("--root", required=True, help="the repository root")
    a = ap.parse_args()
    out = subprocess.run([a.keys], check=True, capture_output=True, text=True).stdout
    code = json.loads(out)
    code["scene_keys"] = set(code["scene_keys"]) | fenicsx_keys(a.root)
    doc = read_page(a.page)
    errors = check(code, doc)
    for e in errors:
        print(f"{a.page}: {e}")
    if errors:
        return 1
    print(f"check_scene_format: {len(code['scene_keys'])} scene keys, {len(doc['history'])} history columns, "
          f"{sum(len(v) for v in doc['summary'].values())} summary.json keys documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
