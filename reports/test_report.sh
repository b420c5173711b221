#!/usr/bin/env bash
# @brief ctest report_render: renders a small report.html (a fixture verification run with one
# failing gate, plus the committed figure sets: reports/render.py report) and checks it in headless
# Chromium (reports/check_report.py: the verdict block first and within the first 1000 px of a
# 1400x1000 window, a failing scene first in the scorecard, every image a separate decodable PNG,
# no section empty, the page under 2 MB, the screenshot not blank; --self-test: broken copies of the
# page are rejected). Fails, with a message, when chromium is absent.
# Usage: reports/test_report.sh OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: reports/test_report.sh OUT_DIR}
rm -rf "$out" && mkdir -p "$out"
/usr/bin/python3 reports/render.py report --verify reports/testdata/verify --figures reports/testdata/figure_set \
  --committed --out "$out/report.html"
/usr/bin/python3 reports/check_report.py "$out/report.html" --screenshot "$out/report.png" --self-test
