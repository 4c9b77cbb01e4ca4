#!/usr/bin/env bash
# The main job on bundled data: convert every bundled mesh to .spt in parallel, then
# describe what was built. Usage: tools/demo.sh BUILD_DIR
set -euo pipefail
build=${1:-build}
spt="$build/cli/spt"
out="$build/demo"
mkdir -p "$out"
echo "== spt convert: bundled meshes -> $out/*.spt"
"$spt" convert resources/meshes/* --out-dir "$out" --force
echo
echo "== the CAD part with a tolerance of 0.01 (model units) between two objects"
"$spt" convert resources/meshes/cad_part.stl -o "$out/cad_part_tol.spt" --tolerance 0.01 --force
echo
echo "== spt info $out/figure.spt"
"$spt" info "$out/figure.spt"
echo
echo "== spt query: the torus against the figure, moving along -x, at three poses"
printf '%s\n' '# tx ty tz qw qx qy qz dx dy dz' '0.3 1.0 0 1 0 0 0 -1 0 0' '0.9 1.0 0 1 0 0 0 -1 0 0' '3 1 0 1 0 0 0' > "$out/poses.txt"
"$spt" query "$out/figure.spt" "$out/torus.spt" --poses "$out/poses.txt" --mode deepest

echo
echo "== spt render: the figure in the four views, sampling spheres by node -> $out/figure.png"
"$spt" render resources/meshes/figure.obj --tree "$out/figure.spt" --view quad \
  --overlay spheres,bounds,grid,axes --node 2 --color-by node -o "$out/figure.png"
echo "wrote $out/figure.png"
