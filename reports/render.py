#!/usr/bin/env python3
"""@brief The one HTML generator of beamimpact: every page (the verification report, a method's
scorecard, a conformance result) is rendered here from the JSON the C++ program writes, with the
Jinja2 templates of reports/templates/ (Debian python3-jinja2).

Usage:
  render.py report --verify DIR [--committed] [--figures DIR ...] --out FILE
      DIR/norms.json of `beamimpact verify`, plus figure sets (DIR/figures.json manifests:
      {"title", "about", "figures": [{"png", "title", "command", "scene", "version", "caption"}],
      "tables": [{"title", "columns", "rows"}]}); --committed adds every committed set
      (figure_sets.FIGURE_SETS, reports/NAME) after those of --figures, but for a set of the same
      name given with --figures (a set remade by this build replaces the committed one). The figures are copied to
      FILE's folder, figures/SET/..., and loaded lazily; the page itself stays small.
  render.py scorecard DIR [--out FILE]     DIR/scorecard.json of `beamimpact score` -> DIR/scorecard.html,
      with the diagrams of DIR/figures.json (reports/scorecard_figures.py) embedded when it exists:
      the page stays one file
  render.py conform DIR [--out FILE]       DIR/conform.json of `beamimpact conform` -> DIR/conform.html
`beamimpact score` and `beamimpact conform` run the scorecard and conform pages themselves
(tools/beamimpact/page.cc) from the data root: the repository or the installed share/beamimpact.
A figure set whose manifest is missing is shown as "not generated" with the command that makes it.
Exit 2 on bad input (a missing norms.json, a manifest or gate without a key), naming file and key;
exit 3 when Jinja2 is missing (Debian python3-jinja2), with one line saying so.
"""
import argparse
import os
import sys

try:
    import jinja2
except ImportError:
    print("render: Jinja2 is missing (Debian: apt-get install python3-jinja2)", file=sys.stderr)
    sys.exit(3)

from figure_sets import FIGURE_SETS, InputProblem, load_json
from report_files import write_text_atomic

HERE = os.path.dirname(os.path.abspath(__file__))


def environment():
    """@brief The templates of reports/templates, HTML-escaped, undefined names an error."""
    return jinja2.Environment(loader=jinja2.FileSystemLoader(os.path.join(HERE, "templates")),
                              autoescape=True, undefined=jinja2.StrictUndefined,
                              trim_blocks=True, lstrip_blocks=True)


def render_report(a):
    import report_page
    if a.committed:  # a set remade into another folder (--figures out/figures/NAME) replaces the committed one
        given = {os.path.basename(os.path.normpath(d)) for d in a.figures}
        a.figures += [os.path.join(HERE, name) for name in FIGURE_SETS if name not in given]
    out_dir = os.path.dirname(os.path.abspath(a.out))
    os.makedirs(out_dir, exist_ok=True)
    ctx = report_page.context(a.verify, a.figures, out_dir)
    return environment().get_template("report.html.j2").render(**ctx)


def render_scorecard(a):
    import scorecard_page
    card = load_json(os.path.join(a.dir, "scorecard.json"), "a `beamimpact score` result")
    manifest = os.path.join(a.dir, "figures.json")
    figures = load_json(manifest, "reports/scorecard_figures.py's manifest") if os.path.isfile(manifest) else None
    return environment().get_template("scorecard.html.j2").render(**scorecard_page.context(card, figures, a.dir))


def render_conform(a):
    import conform_page
    return environment().get_template("conform.html.j2").render(
        **conform_page.context(load_json(os.path.join(a.dir, "conform.json"), "a `beamimpact conform` result")))


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="page", required=True)
    r = sub.add_parser("report", help="the verification report (norms.json + figure sets)")
    r.add_argument("--verify", required=True, help="a `beamimpact verify` output directory")
    r.add_argument("--figures", action="append", default=[], help="a figure set directory (repeatable)")
    r.add_argument("--committed", action="store_true", help="add every committed figure set (reports/NAME)")
    r.add_argument("--out", required=True, help="the page (its figures go to figures/ beside it)")
    for name, what in (("scorecard", "scorecard.json"), ("conform", "conform.json")):
        s = sub.add_parser(name, help=f"DIR/{what} -> DIR/{name}.html")
        s.add_argument("dir")
        s.add_argument("--out", default="")
    a = p.parse_args(argv)
    if a.page != "report" and not a.out:
        a.out = os.path.join(a.dir, f"{a.page}.html")
    return a


def main(argv=None):
    a = parse(argv)
    try:
        page = {"report": render_report, "scorecard": render_scorecard, "conform": render_conform}[a.page](a)
    except InputProblem as e:
        print(f"render: {e}", file=sys.stderr)
        sys.exit(2)
    write_text_atomic(a.out, page)  # never a half-written page
    print(f"{a.page}: {a.out} ({len(page.encode()) / 1e3:.0f} kB)")


if __name__ == "__main__":
    main()
