#!/usr/bin/env python3
"""@brief Checks that a report.html looks right in a browser: it opens with the scorecard (the first
section, on the first screen) and, when a gate failed, a failing scene is its first row; every
embedded image is a complete, decodable PNG, every section has content, headless Chromium loads
every image (none broken) and its screenshot of the page is a non-blank PNG.

Usage: check_report.py REPORT.html [--screenshot OUT.png] [--self-test]
--self-test  also checks that the checks bite: copies with one image corrupted, one section
             emptied, the scorecard removed, or a passing row moved above the failing ones must
             all be rejected.
Exit 0 when the report passes, 1 with one line per problem otherwise (Chromium missing included:
the check cannot be done without it, which is a failure, not a pass).
"""
import argparse
import base64
import binascii
import html.parser
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

import numpy as np
import matplotlib.image as mpimg

CHROMIUM_TIMEOUT = 60  # s; a headless load of a few MB of base64 takes 1-5 s on a loaded 2-core machine
FIRST_SCREEN = 600     # px: the scorecard must start within the first screen of headless Chromium's window


class Page(html.parser.HTMLParser):
    """Sections (h2 title, text, images) and every <img> src of the page."""

    def __init__(self):
        super().__init__()
        self.sections, self.images, self._sec, self._in_h2 = [], [], None, False
        self.scorecard = None  # {"section": index, "failed": n, "rows": [status, ...]}

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self._sec = {"title": "", "text": "", "images": 0, "tables": 0}
            self.sections.append(self._sec)
        elif tag == "h2":
            self._in_h2 = True
        elif tag == "img":
            self.images.append(a.get("src", ""))
            if self._sec is not None:
                self._sec["images"] += 1
        elif tag == "table" and self._sec is not None:
            self._sec["tables"] += 1
            if a.get("id") == "scorecard" and self.scorecard is None:
                self.scorecard = {"section": len(self.sections) - 1, "failed": int(a.get("data-failed", "0")), "rows": []}
        elif tag == "tr" and self.scorecard is not None and "data-status" in a and self._sec is self.sections[self.scorecard["section"]]:
            self.scorecard["rows"].append(a["data-status"])

    def handle_endtag(self, tag):
        if tag == "section":
            self._sec = None
        elif tag == "h2":
            self._in_h2 = False

    def handle_data(self, data):
        if self._sec is None:
            return
        self._sec["title" if self._in_h2 else "text"] += data


def png_problem(data):
    """None for a complete PNG (signature, chunk CRCs, IHDR..IEND, IDAT inflating to the size the
    header implies), else what is wrong."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return "no PNG signature"
    pos, idat, ihdr, end = 8, b"", None, False
    while pos + 8 <= len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if len(body) != n or pos + 12 + n > len(data):
            return f"chunk {kind!r} truncated"
        (crc,) = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
        if zlib.crc32(kind + body) != crc:
            return f"chunk {kind!r}: bad CRC"
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            end = True
            break
        pos += 12 + n
    if ihdr is None or not end:
        return "IHDR or IEND missing"
    w, h, depth, colour, _, _, interlace = ihdr
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour)
    if channels is None or depth not in (8, 16) and colour != 3 or interlace != 0:
        return None  # a layout this check does not size; the browser check still covers it
    try:
        raw = zlib.decompress(idat)
    except zlib.error as e:
        return f"image data does not inflate ({e})"
    expected = h * (1 + w * channels * depth // 8)
    return None if len(raw) == expected else f"image data {len(raw)} bytes, header implies {expected}"


def static_problems(text):
    page = Page()
    page.feed(text)
    problems = []
    if not page.sections:
        problems.append("no <section> in the page")
    for s in page.sections:
        if not s["text"].strip() and s["images"] == 0 and s["tables"] == 0:
            problems.append(f"section '{s['title'].strip()}' is empty")
    card = page.scorecard
    if card is None or card["section"] != 0:
        problems.append("the report does not open with the scorecard (table id=scorecard in the first section)")
    elif not card["rows"]:
        problems.append("the scorecard has no row")
    elif card["failed"] and card["rows"][0] != "fail":
        problems.append(f"{card['failed']} gate(s) failed but the scorecard's first row is '{card['rows'][0]}', not a failing scene")
    for i, src in enumerate(page.images):
        m = re.match(r"data:image/png;base64,(.*)$", src, re.S)
        if not m:
            problems.append(f"image {i + 1}: not an embedded PNG (src starts {src[:40]!r})")
            continue
        try:
            data = base64.b64decode(m.group(1), validate=True)
        except binascii.Error as e:
            problems.append(f"image {i + 1}: bad base64 ({e})")
            continue
        p = png_problem(data)
        if p:
            problems.append(f"image {i + 1}: {p}")
    return problems, len(page.images)


def chromium():
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        print("check_report: FAIL: chromium not found; install the Debian package chromium "
              "(bash tools/install-deps.sh); the rendering check cannot be done without it", file=sys.stderr)
        sys.exit(1)
    return exe


def run_chromium(exe, report, extra, workdir):
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           f"--user-data-dir={workdir}/profile", "--virtual-time-budget=10000", *extra,
           "file://" + os.path.abspath(report)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=CHROMIUM_TIMEOUT)
    if r.returncode != 0:
        raise RuntimeError(f"chromium exited {r.returncode}: {r.stderr.strip()[-300:]}")
    return r.stdout


def browser_problems(exe, report, n_images, screenshot, failed=0):
    """What the browser shows wrong: broken images; the scorecard off the first screen or, when
    `failed` gates failed, not led by a failing scene; a blank screenshot."""
    problems = []
    with tempfile.TemporaryDirectory() as work:
        dom = run_chromium(exe, report, ["--dump-dom"], work)
        m = re.search(r'<body[^>]*data-images="(\d+)"[^>]*data-broken-images="(\d+)"', dom)
        if not m:
            problems.append("browser: the page's image check did not run (no data-images on <body>)")
        else:
            seen, broken = int(m.group(1)), int(m.group(2))
            if seen != n_images:
                problems.append(f"browser: sees {seen} images, the HTML has {n_images}")
            if broken:
                problems.append(f"browser: {broken} image(s) broken")
        top = re.search(r'<body[^>]*data-scorecard-top="([^"]*)"', dom)
        first = re.search(r'<body[^>]*data-first-row="([^"]*)"', dom)
        if not top or not top.group(1).lstrip("-").isdigit() or int(top.group(1)) > FIRST_SCREEN:
            problems.append(f"browser: the scorecard is not on the first screen (top {top.group(1) if top else 'unknown'} px)")
        if failed and (not first or first.group(1) != "fail"):
            problems.append(f"browser: {failed} gate(s) failed but the first scorecard row is "
                            f"'{first.group(1) if first else 'unknown'}'")
        if screenshot:
            run_chromium(exe, report, [f"--screenshot={os.path.abspath(screenshot)}", "--window-size=1200,2000"], work)
            if not os.path.exists(screenshot):
                problems.append("browser: no screenshot written")
            else:
                with open(screenshot, "rb") as f:
                    p = png_problem(f.read())
                if p:
                    problems.append(f"screenshot: {p}")
                else:
                    px = mpimg.imread(screenshot)[..., :3].reshape(-1, 3)
                    # A blank page is one colour; text, tables and plots give thousands. 8 levels per
                    # channel make the count robust to antialiasing noise.
                    colours = len(np.unique((px * 7).round(), axis=0))
                    white = float(np.mean(px.min(axis=1) > 0.97))
                    if colours < 20 or white > 0.995:
                        problems.append(f"screenshot: blank ({colours} colour levels, {white:.1%} white)")
    return problems


def failed_gates(text):
    """The number of failed gates the scorecard declares (0 without a scorecard)."""
    m = re.search(r'<table[^>]*id=scorecard[^>]*data-failed=(\d+)', text)
    return int(m.group(1)) if m else 0


def check(report, screenshot, exe):
    with open(report, encoding="utf-8") as f:
        text = f.read()
    problems, n_images = static_problems(text)
    if not problems:
        problems += browser_problems(exe, report, n_images, screenshot, failed_gates(text))
    return problems


def self_test(report, exe):
    """The checks must reject a corrupted image (both in Python and in the browser) and an empty section."""
    with open(report, encoding="utf-8") as f:
        text = f.read()
    failures = []
    m = re.search(r'src="data:image/png;base64,([^"]{200})', text)
    if not m:
        return ["self-test: the report has no embedded image to corrupt"]
    # Valid base64 but a broken PNG: bytes overwritten in the middle, or the signature overwritten.
    mid = m.start(1) + 100
    damaged = text[:mid] + "AAAAAAAA" + text[mid + 8:]
    corrupted = text[:m.start(1)] + "AAAAAAAA" + text[m.start(1) + 8:]
    emptied = re.sub(r'(<section id="s0"><h2>[^<]*</h2>).*?(</section>)', r"\1\2", text, count=1, flags=re.S)
    no_card = re.sub(r'<table class=scorecard id=scorecard.*?</table>', "<p>scores</p>", text, count=1, flags=re.S)
    rows = re.search(r'(<tbody>)(<tr data-status=fail>.*?</tr>)(<tr data-status=pass>.*?</tr>)', text, re.S)
    if not rows:
        return failures + ["self-test: the report's scorecard has no failing row above a passing one to swap"]
    pass_first = text[:rows.start(2)] + rows.group(3) + rows.group(2) + text[rows.end(3):]
    with tempfile.TemporaryDirectory() as work:
        for name, variant in (("damaged image", damaged), ("corrupted image", corrupted), ("empty section", emptied),
                              ("scorecard removed", no_card), ("passing scene above the failing ones", pass_first)):
            if not static_problems(variant)[0]:
                failures.append(f"self-test: a report with a {name} passed the static check")
        # The browser on its own must see the corrupted image as broken.
        path = os.path.join(work, "corrupted.html")
        with open(path, "w", encoding="utf-8") as f:
            f.write(corrupted)
        n = static_problems(corrupted)[1]
        if not any("broken" in p for p in browser_problems(exe, path, n, None)):
            failures.append("self-test: chromium did not report the corrupted image as broken")
        # ... and a passing scene above the failing one, and a missing scorecard.
        for name, variant, word in (("passing scene first", pass_first, "first scorecard row"),
                                    ("scorecard removed", no_card, "not on the first screen")):
            path = os.path.join(work, "variant.html")
            with open(path, "w", encoding="utf-8") as f:
                f.write(variant)
            found = browser_problems(exe, path, static_problems(variant)[1], None, failed_gates(text))
            if not any(word in p for p in found):
                failures.append(f"self-test: chromium did not reject the report with the {name}")
    return failures


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("report")
    p.add_argument("--screenshot")
    p.add_argument("--self-test", action="store_true")
    a = p.parse_args()
    exe = chromium()
    problems = check(a.report, a.screenshot, exe)
    if a.self_test:
        problems += self_test(a.report, exe)
    for q in problems:
        print(f"check_report: {a.report}: {q}", file=sys.stderr)
    if problems:
        sys.exit(1)
    print(f"check_report: {a.report}: ok")
