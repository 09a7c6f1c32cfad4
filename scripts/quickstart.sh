#!/usr/bin/env bash
# The README's main job: installs what is missing, builds, and fits a sphere to a bundled CC0
# scan (one sphere of CGAL's spheres.ply), printing the fitted model and its residual figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/apps/implicitfit fit datasets/data/cgal_sphere_single.xyz --model sphere \
  --out build/quickstart_sphere.json --report build/quickstart_report.json
echo "model: build/quickstart_sphere.json  report: build/quickstart_report.json"
