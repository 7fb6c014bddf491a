#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the screenshots of the main views for the README and docs/ under Xvfb, by running the
# GUI tests that drive those views with TOLTURN_SCREENSHOTS set, and writes the PDF report of the
# stepped-shaft example as PNG pages (poppler's pdftoppm): the window at 1366 x 768 and 1600 x 1000,
# its first start, the planning dock (its cutting window and clamping ranking), the feature editor, the import dialog, the solid check,
# the Milling dock, every report page.
# Usage: tools/screenshots.sh [BUILD_DIR] [OUT_DIR]   (defaults: build/dev docs/images)
set -eu
build=${1:-build/dev}
out=${2:-docs/images}
mkdir -p "$out"
out=$(cd "$out" && pwd)
for test in tst_planning_panel tst_feature_panel tst_cad_import tst_main_window tst_measurements_panel tst_setup_panel \
    tst_solid_check_dialog tst_milling_panel; do
    TOLTURN_SCREENSHOTS="$out" xvfb-run -a -s "-screen 0 1680x1050x24" "$build/tests/$test" >/dev/null
done
QT_QPA_PLATFORM=offscreen "$build/app/tolturn-cli" report --planner "A. Planner" -o "$out/report.pdf" \
    resources/examples/stepped-shaft-chuck.tolturn >/dev/null
pdftoppm -r 60 -png "$out/report.pdf" "$out/report-page"
rm "$out/report.pdf"
ls "$out"
