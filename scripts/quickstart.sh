#!/usr/bin/env bash
# The README's main job: installs what is missing, builds only the `implicitfit` command line
# (scripts/test.sh builds the tests), and fits a plane to a real scan: the bundled Kinect scan
# of a milk carton (PCL's test/milk.pcd, BSD-3; 13 704 points, no normals, the sensor's
# viewpoint in the PCD header). It prints the fitted model, the fit's figures and the report:
# parameters with their standard deviations, residual figures, and what was done to the normals
# (estimated by PCA, oriented toward the viewpoint).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target implicitfit
./build/apps/implicitfit fit datasets/data/pcl_milk_carton_kinect.pcd --model plane \
  --out build/quickstart_plane.json --report build/quickstart_report.json
echo "report (build/quickstart_report.json):"
cat build/quickstart_report.json
echo "model: build/quickstart_plane.json  report: build/quickstart_report.json"
