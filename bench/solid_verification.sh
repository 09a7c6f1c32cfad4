#!/bin/sh
# Which raw scans `implicitfit reconstruct` turns into a verified solid, and why the others fail
# (fit/reconstruct/solid_verification.h), on the user's path: points only, no labels.
#   - the Fit4CAD parts of ../shared/data/fit4cad (x y z of the .xyzl files, labels dropped),
#   - CGAL's box on ground, points only and with its own normals,
#   - the Kinect milk carton bundled in datasets/data,
#   - the generated solids (rounded box, plate with filleted bore, boss on slab:
#     datasets/generators/generated_solids.h), sampled by `sample` with noise 0.2% of the size and
#     the normals stripped; each truth is also verified against its own cloud (the verifier must
#     accept it: with the exact normals, and with the normals `reconstruct` estimates).
# Each cloud: `reconstruct CLOUD --keep-unverified --report R.json`, then one row of the
# report's verification: verified, proven bounded, inside/outside agreement, explained share,
# solid pieces, cavities, the verification's and the whole run's seconds, and the first failure.
# Usage: bench/solid_verification.sh path/to/implicitfit [SHARED_DATA=../shared/data] [WORKDIR]
set -eu
cli=${1:?usage: $0 path/to/implicitfit [shared-data] [workdir]}
root=$(cd "$(dirname "$0")/.." && pwd)
data=${2:-$root/../shared/data}
work=${3:-$(mktemp -d /tmp/implicitfit_verify_bench.XXXXXX)}
mkdir -p "$work"
cd "$work"

row() {  # name cloud
  start=$(date +%s.%N)
  "$cli" reconstruct "$2" --out "$1.model.json" --report "$1.report.json" --keep-unverified \
    --quiet > /dev/null 2> "$1.err" || true
  end=$(date +%s.%N)
  python3 - "$1" "$start" "$end" <<'EOF'
import json, sys
name, start, end = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
try:
    r = json.load(open(name + ".report.json"))
except Exception:
    print("| %s | no report: %s |" % (name, open(name + ".err").read().strip()[:120]))
    sys.exit()
v = r.get("verification")
if not v:
    print("| %s | - | - | - | - | - | - | - | %.1f | %s |" % (name, end - start, r["message"][:160]))
    sys.exit()
io, p = v["inside_outside"], v["pieces"]
print("| %s | %s | %s | %.4f | %.3f | %d | %d | %.1f | %.1f | %s |" % (
    name, "yes" if v["verified"] else "no", "yes" if v["bounded"]["proven"] else "no",
    io["agreement"], io["explained"], p["solids"], p["cavities"], v["seconds"], end - start,
    (v["failures"][0][:160] if v["failures"] else "")))
EOF
}

truth_row() {  # name truth cloud-with-normals points-only-cloud
  a=$("$cli" verify "$2" "$3" --quiet > /dev/null 2>&1 && echo yes || echo no)
  b=$("$cli" verify "$2" "$4" --quiet > "$1.truth.json" 2>/dev/null && echo yes ||
      python3 -c "import json,sys; print('no: ' + json.load(open('$1.truth.json'))['failures'][0][:120])")
  echo "| $1 (truth) | exact normals: $a | estimated normals: $b |"
}

echo "| cloud | verified | bounded | agreement | explained | solids | cavities | verify s | run s | first failure |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for part in test_PC21 test_PC33 test_PC34 test_PC35 train_PC124 train_PC131 train_PC145 train_PC155; do
  f="$data/fit4cad/fit4cad_$part.xyzl"
  [ -f "$f" ] || { echo "| $part | absent |"; continue; }
  awk '{ print $1, $2, $3 }' "$f" > "$part.xyz"
  row "$part" "$part.xyz"
done
box="$data/cgal/cgal_point_set_3_box_on_ground.xyz"
if [ -f "$box" ]; then
  awk '{ print $1, $2, $3 }' "$box" > box_on_ground_points.xyz
  row box_on_ground_points box_on_ground_points.xyz
  cp "$box" box_on_ground_normals.xyz
  row box_on_ground_normals box_on_ground_normals.xyz
fi
row milk_carton "$root/datasets/data/pcl_milk_carton_kinect.pcd"

plane() { printf '{"type": "plane", "normal": [%s], "offset": %s}' "$1" "$2"; }
faces() {  # hx hy hz
  printf '%s,%s,%s,%s,%s,%s' "$(plane -1,0,0 "$1")" "$(plane 1,0,0 "$1")" "$(plane 0,-1,0 "$2")" \
    "$(plane 0,1,0 "$2")" "$(plane 0,0,-1 "$3")" "$(plane 0,0,1 "$3")"
}
model() { printf '{"format": "implicitfit-model", "version": 1, "root": %s}\n' "$1"; }
model "{\"type\": \"intersection\", \"delta\": 0.2, \"epsilon\": 0.12, \"order\": 3, \"children\": [$(faces 1 0.7 0.5)]}" > rounded_box.truth.json
model "{\"type\": \"difference\", \"delta\": 0.15, \"epsilon\": 0.1, \"order\": 3, \"children\": [{\"type\": \"intersection\", \"delta\": 0.1, \"epsilon\": 0.1, \"order\": 0, \"children\": [$(faces 1 1 0.25)]}, {\"type\": \"cylinder\", \"point\": [0.1, 0, 0], \"axis\": [0, 0, 1], \"radius\": 0.4}]}" > plate_with_bore.truth.json
model "{\"type\": \"union\", \"delta\": 0.15, \"epsilon\": 0.1, \"order\": 3, \"children\": [{\"type\": \"intersection\", \"delta\": 0.1, \"epsilon\": 0.1, \"order\": 0, \"children\": [$(faces 1 1 0.2)]}, {\"type\": \"intersection\", \"delta\": 0.1, \"epsilon\": 0.1, \"order\": 0, \"children\": [{\"type\": \"cylinder\", \"point\": [0, 0.1, 0], \"axis\": [0, 0, 1], \"radius\": 0.35}, $(plane 0,0,1 0.8), $(plane 0,0,-1 0.2)]}]}" > boss_on_slab.truth.json
# name, noise (0.2% of the largest extent, 2.2)
set -- rounded_box 0.0044 plate_with_bore 0.0044 boss_on_slab 0.0044
truths=""
while [ $# -ge 2 ]; do
  "$cli" sample "$1.truth.json" --count 20000 --noise "$2" --seed 7 --out "$1.cloud.xyz" > /dev/null
  awk '{ print $1, $2, $3 }' "$1.cloud.xyz" > "$1.points.xyz"
  row "$1" "$1.points.xyz"
  truths="$truths $1"
  shift 2
done
echo
for t in $truths; do truth_row "$t" "$t.truth.json" "$t.cloud.xyz" "$t.points.xyz"; done
