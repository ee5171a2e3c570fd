#!/usr/bin/env bash
# Sets up, builds and runs the main job: consistent-remesh with no model
# arguments, which takes the CGAL quadrupeds of Debian's libcgal-demo
# (installed by setup.sh) with the landmarks and base domain shipped in
# Data/cgal-quadrupeds, remeshes them with one connectivity, and writes the
# mean, PCA modes, blends, a texture transfer and report.md/report.html with
# pictures. Results go to ./results (or the folder given as $1).
set -euo pipefail
cd "$(dirname "$0")"
./setup.sh

output="${1:-results}"
command=("${CMP_BUILD_DIR:-build}/bin/consistent-remesh" --output "$output")
# The pictures need an X display; a machine without one gets Xvfb's.
if [ -z "${DISPLAY:-}" ]; then
  command=(xvfb-run -a "${command[@]}")
fi
"${command[@]}"
echo "run-example: open $output/report.html (or report.md) for the results and pictures"
