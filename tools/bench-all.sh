#!/usr/bin/env bash
# Runs every measurement docs/benchmarks.md quotes, one after another, into OUT_DIR.
# usage: tools/bench-all.sh [BUILD_DIR] [OUT_DIR]     (default: build, bench-out)
# Needs a Release build with the benchmarks (cmake --build BUILD) and, for the editor,
# xvfb-run. About 3 to 4 minutes on 2 cores; run it on a quiet machine: nothing here is
# pinned, and everything else running shows in the figures.
set -euo pipefail
BUILD=$(realpath "${1:-build}")
OUT=${2:-bench-out}
SRC=$(cd "$(dirname "$0")/.." && pwd)
BIG=$OUT/big
mkdir -p "$OUT"
for exe in cli/spt bench/spt-bench-build bench/spt-bench-scenes bench/spt-bench-cancel \
           bench/spt-editor-bench tools/meshgen/spt-make-resources; do
  [[ -x $BUILD/$exe ]] || { echo "missing $BUILD/$exe: build first (cmake --build $BUILD)" >&2; exit 1; }
done

# Each step's start, with the machine's load, so that a reader can tell a quiet run.
stamp() { echo "=== $1 $(date -u +%FT%TZ) load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$OUT/log.txt"; }

echo "commit $(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo unknown)," \
     "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')" > "$OUT/log.txt"
stamp "1M meshes"
[[ -f $BIG/torus_1m.ply ]] || "$BUILD/tools/meshgen/spt-make-resources" "$BIG" --big > /dev/null

stamp "trees"
"$BUILD/bench/spt-bench-build" > "$OUT/trees.md"
for i in 1 2 3; do
  "$BUILD/bench/spt-bench-build" --threads 1 | grep '^| 1000000 ' > "$OUT/trees_1m_$i.md"
done

stamp "convert"
for i in 1 2 3; do
  for f in ply stl; do
    /usr/bin/time -f "%e s %M KB" -o "$OUT/convert_${f}_$i.txt" \
      "$BUILD/cli/spt" convert "$BIG/torus_1m.$f" --force -q -o "$OUT/t.spt" > /dev/null 2>&1
  done
done
rm -f "$OUT/t.spt"

stamp "render"
"$SRC/tools/bench-render.sh" "$BUILD" 9 > "$OUT/render.md"

stamp "scenes"
"$BUILD/bench/spt-bench-scenes" > "$OUT/scenes.md"
for i in 1 2 3; do
  for t in 2 1; do
    "$BUILD/cli/spt" simulate "$SRC/resources/scenes/pile.json" --steps 160 --threads $t \
      -o "$OUT/pile_t${t}_$i.csv" 2> /dev/null
  done
done

stamp "editor"
for i in 1 2 3; do
  xvfb-run -a -s "-screen 0 1920x1080x24" env QT_QPA_PLATFORM=xcb \
    "$BUILD/bench/spt-editor-bench" > "$OUT/editor_$i.md" 2> /dev/null
done

stamp "cancel"
"$BUILD/bench/spt-bench-cancel" "$BIG/torus_1m.ply" 100 > "$OUT/cancel_ply.md"
"$BUILD/bench/spt-bench-cancel" "$BIG/torus_1m.stl" 100 > "$OUT/cancel_stl.md"
stamp "done"

# The heap of the pile: the median step of 100-150 and its stages' means, each run.
for t in 2 1; do
  for i in 1 2 3; do
    csv=$OUT/pile_t${t}_$i.csv
    median=$(awk -F, 'NR > 1 && $1 >= 100 && $1 <= 150 { print ($11 + $12 + $13 + $14 + $15) / 1e6 }' "$csv" |
             sort -g | sed -n 26p)
    awk -F, -v t=$t -v m="$median" 'NR > 1 && $1 >= 100 && $1 <= 150 { b += $11; n += $12; d += $13; r += $15; k++ }
      END { printf "pile heap, %d thread(s): median step %.2f ms; mean broad / narrow / depth / response %.2f / %.2f / %.2f / %.2f ms\n",
            t, m, b / k / 1e6, n / k / 1e6, d / k / 1e6, r / k / 1e6 }' "$csv"
  done
done | tee "$OUT/pile.txt"
