#!/usr/bin/env bash
# Times the whole `spt render` command, as docs/benchmarks.md ("Rendering") reports it.
# usage: tools/bench-render.sh [BUILD_DIR] [RUNS]     (default: build, 9 runs)
# Prints the median and the fastest wall time and the median CPU time: on a shared
# machine the fastest run is the better estimate of the command's own cost, the
# median shows what contention adds.
# Needs a built tree: the spt command and the test-mesh generator spt_make_test_mesh.
set -euo pipefail
BUILD=${1:-build}
RUNS=${2:-9}
SPT=$BUILD/cli/spt
MAKE_MESH=$BUILD/tests/render/spt_make_test_mesh
for exe in "$SPT" "$MAKE_MESH"; do
  [[ -x $exe ]] || { echo "missing $exe: build first (cmake --build $BUILD)" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$MAKE_MESH" torus "$work/torus100k.ply" 158   # 49,928 vertices, 99,856 triangles
"$MAKE_MESH" figure "$work/figure.obj"         # 1,340 vertices
"$SPT" convert "$work/torus100k.ply" -o "$work/torus100k.spt" -q 2> /dev/null

# "median | fastest | median CPU" of RUNS runs of the command: wall seconds, and
# user + system seconds of the process and its threads (llvmpipe rasterises on
# every core, so CPU can exceed wall time).
time_runs() {
  local walls=() cpus=() out
  "$@" > /dev/null 2>&1 # warm the file cache and Mesa's shader cache
  for ((i = 0; i < RUNS; i++)); do
    out=$( { TIMEFORMAT='%3R %3U %3S'; time "$@" > /dev/null 2>&1; } 2>&1 )
    read -r real user sys <<< "$out"
    walls+=("$real")
    cpus+=("$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.3f", u + s }')")
  done
  local median=$(( (RUNS + 1) / 2 ))
  printf '%s s | %s s | %s s' \
    "$(printf '%s\n' "${walls[@]}" | sort -n | sed -n "${median}p")" \
    "$(printf '%s\n' "${walls[@]}" | sort -n | head -1)" \
    "$(printf '%s\n' "${cpus[@]}" | sort -n | sed -n "${median}p")"
}

row() { # label, command...
  local label=$1
  shift
  printf '| %s | %s | `%s` |\n' "$label" "$(time_runs "$@")" "${*//$work\//}"
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "mesa: $(dpkg-query -W -f '${Version}' libosmesa6 2>/dev/null || echo unknown); $RUNS runs each"
echo
echo "| case | median | fastest | median CPU | command |"
echo "|---|---|---|---|---|"
row "100k triangles + 50k spheres, tree from file" \
  "$SPT" render "$work/torus100k.ply" --tree "$work/torus100k.spt" --overlay spheres,grid,axes --size 512x512 -o "$work/a.png"
row "100k triangles + 50k spheres, egl backend" \
  "$SPT" render "$work/torus100k.ply" --tree "$work/torus100k.spt" --overlay spheres,grid,axes --size 512x512 --backend egl -o "$work/b.png"
row "100k triangles + 50k spheres, tree built in the command" \
  "$SPT" render "$work/torus100k.ply" --overlay spheres,grid,axes --size 512x512 -o "$work/c.png"
row "100k triangles, mesh only" \
  "$SPT" render "$work/torus100k.ply" --size 512x512 -o "$work/d.png"
row "small mesh (1.3k vertices)" \
  "$SPT" render "$work/figure.obj" --size 512x512 -o "$work/e.png"
row "small mesh, quad layout with spheres" \
  "$SPT" render "$work/figure.obj" --view quad --overlay spheres,grid,axes --size 512x512 -o "$work/f.png"
# What a fresh machine or user pays once: llvmpipe compiles every shader with LLVM.
row "first case, Mesa's shader cache off" env MESA_SHADER_CACHE_DISABLE=true \
  "$SPT" render "$work/torus100k.ply" --tree "$work/torus100k.spt" --overlay spheres,grid,axes --size 512x512 -o "$work/g.png"
row "small mesh, Mesa's shader cache off" env MESA_SHADER_CACHE_DISABLE=true \
  "$SPT" render "$work/figure.obj" --size 512x512 -o "$work/h.png"
echo
echo "steps of the first case (--timings):"
"$SPT" render "$work/torus100k.ply" --tree "$work/torus100k.spt" --overlay spheres,grid,axes --size 512x512 \
  -o "$work/a.png" --timings 2>&1 | sed 's/^/    /'
