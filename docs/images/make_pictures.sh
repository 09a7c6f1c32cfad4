#!/usr/bin/env bash
# Re-makes the pictures of docs/view.md and the README from the real scans of ../shared/data
# (Fit4CAD PC34, GPL-3; CGAL's kitten, CC0: only the pictures are kept here, not the data).
# Needs a build (bash scripts/build.sh) and Chromium. Usage: bash docs/images/make_pictures.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=${IMPLICITFIT_CLI:-build/apps/implicitfit}
data=${IMPLICITFIT_SHARED_DATA:-../shared/data}
pc34=$data/fit4cad/fit4cad_test_PC34.xyzl
kitten=$data/cgal/cgal_kitten.xyz
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=900x600
# 1. detect's segmentation of PC34, coloured by primitive, with its legend.
"$cli" detect "$pc34" --out "$work/pc34.scene.json" --ply "$work/pc34.seg.ply" > /dev/null
"$cli" view "$work/pc34.scene.json" "$work/pc34.seg.ply" --title "detect: Fit4CAD PC34" \
  --png docs/images/pc34_segmentation.png --size $size --quiet
# 2. reconstruct's solid of PC34 (on detect's primitives), cut through the shank's axis and seen
#    from the cut side: red is the solid's material, blue its outside (the socket).
"$cli" reconstruct "$pc34" --out "$work/pc34.solid.json" > /dev/null
"$cli" view "$pc34" "$work/pc34.solid.json" --title "reconstruct: PC34 solid, cut through the shank" \
  --clip=-y,0.5 --option hide=0 --png docs/images/pc34_solid_clipped.png --size $size --quiet
# 3. a C1 Bernstein patch mesh fitted to the kitten, the scan coloured by f of the mesh.
"$cli" fit "$kitten" --model patch-mesh --out "$work/kitten.mesh.json" > /dev/null
"$cli" view "$kitten" "$work/kitten.mesh.json" --title "fit --model patch-mesh: CGAL kitten" \
  --option up=y --png docs/images/kitten_patch_mesh.png --size $size --quiet
ls -l docs/images/*.png
