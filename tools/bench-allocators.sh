#!/usr/bin/env bash
# Compares builds of `spt` that differ only in their heap (SPT_ALLOCATOR), as docs/benchmarks.md
# ("The programs' heap") reports it: the same commands, one run of each binary a round, rounds
# interleaved so that a slow spell of the machine falls on all of them alike.
# usage: tools/bench-allocators.sh ROUNDS LABEL=SPT_BINARY... (needs build/ for the meshes)
# Prints, per command and binary, the median and fastest wall time, the median CPU time (user +
# system, less moved by other work on a shared machine), minor page faults and peak RSS.
set -euo pipefail
ROUNDS=$1; shift
for pair in "$@"; do # a label is one word: the tables are read back by field
  [[ ${pair%%=*} =~ ^[^[:space:]]+$ && $pair == *=* ]] || { echo "bad LABEL=SPT_BINARY: '$pair'" >&2; exit 1; }
done
BUILD=${BUILD:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -f bench-out/big/torus_1m.ply ]] || "$BUILD/tools/meshgen/spt-make-resources" bench-out/big --big > /dev/null
big=bench-out/big
commands=(
  "--version"
  "render resources/meshes/figure.obj --size 512x512 -o $work/f.png"
  "convert resources/meshes/figure.obj --force -q -o $work/f.spt"
  "convert $big/torus_1m.ply --force -q -o $work/t.spt"
  "convert $big/torus_1m.stl --force -q -o $work/t.spt"
)
for ((r = 0; r < ROUNDS; r++)); do
  for c in "${!commands[@]}"; do
    for pair in "$@"; do
      label=${pair%%=*}; bin=${pair#*=}
      # shellcheck disable=SC2086
      start=$(date +%s%N)
      /usr/bin/time -f "%M %U %S %R" -o "$work/t" "$bin" ${commands[$c]} > /dev/null 2>&1
      end=$(date +%s%N)
      read -r rss user sys faults < "$work/t"
      echo "$c $label $(( (end - start) / 1000 )) $rss $(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }') $faults" >> "$work/all"
    done
  done
done
echo "| command | heap | median s | fastest s | median CPU s | median minor faults | median peak RSS MB |"
echo "|---|---|---:|---:|---:|---:|---:|"
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
for c in "${!commands[@]}"; do
  shown="spt ${commands[$c]//$work\//}"
  for pair in "$@"; do
    label=${pair%%=*}
    awk -v c="$c" -v l="$label" '$1 == c && $2 == l { print $3, $4, $5, $6 }' "$work/all" > "$work/cell"
    col() { cut -d' ' -f"$1" "$work/cell"; }
    printf '| `%s` | %s | %.3f | %.3f | %.2f | %d | %d |\n' "$shown" "$label" "$(col 1 | median | awk '{ print $1 / 1e6 }')" \
      "$(col 1 | sort -n | head -1 | awk '{ print $1 / 1e6 }')" "$(col 3 | median)" "$(col 4 | median)" \
      "$(( $(col 2 | median) / 1024 ))"
  done
done
