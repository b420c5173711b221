#!/usr/bin/env bash
# @brief ctest report_render: writes a small report.html (a fixture verification run plus the
# committed figure sets) and checks it in headless Chromium (reports/check_report.py: the scorecard
# first and led by the failing scene, images decode, no section empty, no image broken in the
# browser, the screenshot is not blank; --self-test: a corrupted image, an empty section, a missing
# scorecard and a passing scene first are rejected). Fails, with a message, when chromium is absent.
# Usage: reports/test_report.sh OUT_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: reports/test_report.sh OUT_DIR}
rm -rf "$out" && mkdir -p "$out"
/usr/bin/python3 reports/html_report.py --verify reports/testdata/verify --figures reports/testdata/figure_set \
  --committed --out "$out/report.html"
/usr/bin/python3 reports/check_report.py "$out/report.html" --screenshot "$out/report.png" --self-test
