#!/usr/bin/env python3
"""@brief Checks that a report.html (reports/render.py report) looks right in a browser: it opens
with the verdict block, which ends within the first 1000 px of a 1400x1000 window; when a gate
failed, the scorecard's first row is a failing scene; every section has content; every image is a
separate, complete PNG file beside the page (none embedded) that headless Chromium decodes; the page
itself is under 2 MB; a 1400x1000 screenshot is not blank.

Usage: check_report.py REPORT.html [--screenshot OUT.png] [--self-test]
--self-test  also checks that the checks bite: copies with one image corrupted, one section emptied,
             the verdict removed or pushed below the first screen, a passing row above the failing
             ones, or an image embedded in a page over 2 MB must all be rejected.
Exit 0 when the report passes, 1 with one line per problem otherwise (Chromium missing included:
the check cannot be done without it, which is a failure, not a pass).
"""
import argparse
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

CHROMIUM_TIMEOUT = 60   # s; a headless load of the page and its lazy images takes 1-5 s on a loaded 2-core machine
WINDOW = (1400, 1000)   # px: the first screen of a laptop; the verdict block must end inside it
PAGE_LIMIT = 2_000_000  # bytes of HTML: the page loads fast; figures are separate files


class Page(html.parser.HTMLParser):
    """Sections (id, h2 title, text, images, tables), every <img> src, the scorecard's rows."""

    def __init__(self):
        super().__init__()
        self.sections, self.images, self._sec, self._in_h2 = [], [], None, False
        self.scorecard = None  # {"failed": n, "rows": [status, ...]}

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self._sec = {"id": a.get("id", ""), "title": "", "text": "", "images": 0, "tables": 0}
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
                self.scorecard = {"failed": int(a.get("data-failed", "0")), "rows": []}
        elif tag == "tr" and self.scorecard is not None and "data-status" in a:
            self.scorecard["rows"].append(a["data-status"])

    def handle_endtag(self, tag):
        if tag == "section":
            self._sec = None
        elif tag == "h2":
            self._in_h2 = False

    def handle_data(self, data):
        if self._sec is not None:
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


def static_problems(text, folder):
    """What is wrong in the HTML itself (and its image files, relative to `folder`)."""
    page = Page()
    page.feed(text)
    problems = []
    if len(text.encode()) > PAGE_LIMIT:
        problems.append(f"the page is {len(text.encode()) / 1e6:.1f} MB, over {PAGE_LIMIT / 1e6:.0f} MB")
    if not page.sections or page.sections[0]["id"] != "verdict":
        problems.append("the report does not open with the verdict block (section id=verdict first)")
    for s in page.sections:
        if not s["text"].strip() and s["images"] == 0 and s["tables"] == 0:
            problems.append(f"section '{s['id'] or s['title'].strip()}' is empty")
    card = page.scorecard
    if card is None or not card["rows"]:
        problems.append("no scorecard (table id=scorecard with rows)")
    elif card["failed"] and card["rows"][0] != "fail":
        problems.append(f"{card['failed']} gate(s) failed but the scorecard's first row is '{card['rows'][0]}'")
    for i, src in enumerate(page.images):
        if src.startswith("data:") or "://" in src or src.startswith("/"):
            problems.append(f"image {i + 1}: not a file beside the page (src starts {src[:40]!r})")
            continue
        path = os.path.join(folder, src)
        if not os.path.isfile(path):
            problems.append(f"image {i + 1}: {src} not found")
            continue
        with open(path, "rb") as f:
            p = png_problem(f.read())
        if p:
            problems.append(f"image {i + 1} ({src}): {p}")
    return problems, len(page.images)


def chromium():
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if not exe:
        print("check_report: FAIL: chromium not found; install the Debian package chromium "
              "(bash tools/install-deps.sh); the rendering check cannot be done without it", file=sys.stderr)
        sys.exit(1)
    return exe


def run_chromium(exe, url, extra, workdir):
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
           f"--user-data-dir={workdir}/profile", "--virtual-time-budget=10000",
           f"--window-size={WINDOW[0]},{WINDOW[1]}", *extra, url]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=CHROMIUM_TIMEOUT)
    if r.returncode != 0:
        raise RuntimeError(f"chromium exited {r.returncode}: {r.stderr.strip()[-300:]}")
    return r.stdout


def body_attr(dom, name):
    m = re.search(rf'<body[^>]*\b{name}="([^"]*)"', dom)
    return m.group(1) if m else None


def blank(screenshot):
    """Why the screenshot is blank or broken, else None."""
    with open(screenshot, "rb") as f:
        p = png_problem(f.read())
    if p:
        return p
    px = mpimg.imread(screenshot)[..., :3].reshape(-1, 3)
    # A blank page is one colour; text and tables give dozens. 8 levels per channel make the count
    # robust to antialiasing noise.
    colours = len(np.unique((px * 7).round(), axis=0))
    white = float(np.mean(px.min(axis=1) > 0.97))
    return f"blank ({colours} colour levels, {white:.1%} white)" if colours < 20 or white > 0.995 else None


def browser_problems(exe, report, n_images, screenshot, images=True):
    """What the browser shows wrong: broken images (when `images`); the verdict block missing or not
    ending within the first screen; a blank screenshot of the first screen."""
    problems = []
    url = "file://" + os.path.abspath(report)
    with tempfile.TemporaryDirectory() as work:
        dom = run_chromium(exe, url + "#check-images", ["--dump-dom"], work) if images else ""
        seen, broken = body_attr(dom, "data-images"), body_attr(dom, "data-broken-images")
        if not images:
            pass
        elif seen is None or broken is None:
            problems.append("browser: the page's image check did not run (no data-images on <body>)")
        else:
            if int(seen) != n_images:
                problems.append(f"browser: sees {seen} images, the HTML has {n_images}")
            if int(broken):
                problems.append(f"browser: {broken} image(s) broken")
        dom = run_chromium(exe, url, ["--dump-dom"], work)
        top, bottom = body_attr(dom, "data-verdict-top"), body_attr(dom, "data-verdict-bottom")
        if not bottom or not bottom.lstrip("-").isdigit() or int(bottom) > WINDOW[1] or int(top) < 0:
            problems.append(f"browser: the verdict block is not within the first {WINDOW[1]} px "
                            f"(top {top}, bottom {bottom})")
        if screenshot:
            run_chromium(exe, url, [f"--screenshot={os.path.abspath(screenshot)}"], work)
            why = blank(screenshot) if os.path.exists(screenshot) else "not written"
            if why:
                problems.append(f"browser: screenshot {why}")
    return problems


def check(report, screenshot, exe):
    with open(report, encoding="utf-8") as f:
        text = f.read()
    problems, n_images = static_problems(text, os.path.dirname(os.path.abspath(report)))
    if not problems:
        problems += browser_problems(exe, report, n_images, screenshot)
    return problems


def variants(text, folder):
    """(name, html, word a browser problem must contain or None) copies of the page, each broken
    one way; the corrupted image is written as a copy beside the page (folder/selftest-bad.png)."""
    m = re.search(r'<img[^>]*src="([^"]+)"', text)
    bad = os.path.join(folder, "selftest-bad.png")
    with open(os.path.join(folder, m.group(1)), "rb") as f:
        data = bytearray(f.read())
    data[len(data) // 2:len(data) // 2 + 8] = b"\0" * 8  # image data broken, chunk CRC wrong
    with open(bad.replace("bad", "damaged"), "wb") as f:
        f.write(bytes(data))
    data[:8] = b"\0" * 8  # no PNG signature: no browser decodes it
    with open(bad, "wb") as f:
        f.write(bytes(data))
    damaged = text[:m.start(1)] + "selftest-damaged.png" + text[m.end(1):]
    corrupted = text[:m.start(1)] + "selftest-bad.png" + text[m.end(1):]
    emptied = re.sub(r'(<section id="where"><h2>[^<]*</h2>).*?(</section>)', r"\1\2", text, count=1, flags=re.S)
    no_verdict = re.sub(r'<section id="verdict".*?</section>', "", text, count=1, flags=re.S)
    pushed = text.replace('<section id="verdict"', '<div style="height:1200px"></div><section id="verdict"', 1)
    big = text.replace("</body>", "<!--" + "x" * PAGE_LIMIT + "--></body>", 1)
    out = [("damaged image", damaged, None), ("corrupted image", corrupted, "broken"), ("empty section", emptied, None),
           ("verdict removed", no_verdict, "verdict"), ("verdict below the first screen", pushed, "verdict"),
           ("page over 2 MB", big, None)]
    rows = re.search(r'(<tbody>)\s*(<tr data-status="fail">.*?</tr>)\s*(<tr data-status="pass">.*?</tr>)', text, re.S)
    if rows:
        out.append(("passing scene above the failing ones",
                    text[:rows.start(2)] + rows.group(3) + rows.group(2) + text[rows.end(3):], None))
    return out, rows is not None


def self_test(report, exe):
    """Every broken copy must be rejected: statically, and in the browser where a word is given
    (a static problem stops the browser check, so the browser is asked directly)."""
    folder = os.path.dirname(os.path.abspath(report))
    with open(report, encoding="utf-8") as f:
        text = f.read()
    failures = []
    found, swapped = variants(text, folder)
    if not swapped:
        failures.append("self-test: the report's scorecard has no failing row above a passing one to swap")
    path = os.path.join(folder, "selftest.html")
    try:
        for name, variant, word in found:
            if name != "verdict below the first screen" and not static_problems(variant, folder)[0]:
                failures.append(f"self-test: a report with a {name} passed the static check")
            if word:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(variant)
                got = browser_problems(exe, path, static_problems(variant, folder)[1], None, images=word == "broken")
                if not any(word in p for p in got):
                    failures.append(f"self-test: chromium did not reject the report with the {name}")
    finally:
        for p in (path, os.path.join(folder, "selftest-bad.png"), os.path.join(folder, "selftest-damaged.png")):
            if os.path.exists(p):
                os.remove(p)
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
