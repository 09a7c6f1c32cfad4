#!/usr/bin/env bash
# The 10^6-point scene (bench/detect_comparison --scale-scene: ground 500 000, five partial
# objects of 80 000, noise 0.3%, 10% outliers, normals in the file) through `implicitfit detect`
# and CGAL's Efficient RANSAC (detect_comparison --cgal, defaults), each under /usr/bin/time -v:
# recall / precision (the benchmark's definitions), elapsed and CPU time, peak RSS and bytes a
# point. Usage: bench/detect_scale.sh BUILD_DIR [WORK_DIR]
set -euo pipefail
build=${1:?build directory}
work=${2:-$(mktemp -d)}
mkdir -p "$work"
"$build/bench/detect_comparison" --scale-scene "$work" >&2
points=$(grep -a -m1 "element vertex" "$work/scene_1e6.ply" | awk '{print $3}')
run() {  # name, command...
  local name=$1; shift
  /usr/bin/time -v "$@" > "$work/$name.out" 2> "$work/$name.time"
  local wall cpu rss
  wall=$(grep "Elapsed (wall clock)" "$work/$name.time" | awk '{print $NF}')
  cpu=$(awk -F': ' '/User time/{u=$2} /System time/{s=$2} END{printf "%.1f", u+s}' "$work/$name.time")
  rss=$(grep "Maximum resident set size" "$work/$name.time" | awk '{print $NF}')
  echo "$name: wall $wall, CPU ${cpu} s, peak RSS $((rss / 1024)) MB = $((rss * 1024 / points)) bytes/point"
}
run implicitfit "$build/apps/implicitfit" detect "$work/scene_1e6.ply" --truth "$work/scene_1e6.truth" \
  --out "$work/scene.json" --report "$work/report.json" --quiet
grep -o '"recall"[^,]*\|"precision"[^,]*\|"recovered"[^,]*' "$work/report.json" | head -3 | tr '\n' ' '; echo
run cgal "$build/bench/detect_comparison" --cgal "$work/scene_1e6.ply" "$work/scene_1e6.truth"
cat "$work/cgal.out"
