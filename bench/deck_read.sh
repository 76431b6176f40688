#!/usr/bin/env bash
# Reading speed and memory of `feticon run DECK.inp` on a deck of about a million nodes: two
# stacked boxes of 100 x 100 x 50 nodes, C3D8, sets, a surface-to-surface contact pair,
# *BOUNDARY and *DLOAD (bench/make_big_deck.py), written in a temporary folder.
#
# feticon has no switch to stop after reading, so the deck has a second pair whose master is its
# slave (--stop-after-reading): the reader refuses it once nodes, cells, bodies, sets and
# surfaces are built, before the solver allocates anything. Two runs under /usr/bin/time -v:
#   outline: --set memory_limit=1, refused by the memory guard after the deck outlines
#            (the line counts run before the output folder is made);
#   read:    the same run with memory_limit=1e12, ended by the deck error after reading.
# Read time = median(read) - median(outline) wall time, the phase summary.json calls "mesh";
# the read run's peak RSS holds the mesh, the reader's tables and the process itself (the
# outline run's peak). The target: at most 2 s and at most 1.5x the mesh's own memory,
# nodes * 24 + cells * (32 + 4) bytes (coordinates, hex8 cells, body ids).
#
#   bench/deck_read.sh                                  # build/feticon, 99 x 99 x 49 cells per box
#   bench/deck_read.sh --feticon build/feticon --cells 49 49 24 --repeat 5
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
cells=(99 99 49)
repeat=3
while [[ $# -gt 0 ]]; do
  case $1 in
    --feticon) feticon=$2; shift 2 ;;
    --cells) cells=("$2" "$3" "$4"); shift 4 ;;
    --repeat) repeat=$2; shift 2 ;;
    *) echo "bench/deck_read.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

work=$(mktemp -d /tmp/feticon-deck-read.XXXXXX)
trap 'rm -rf "$work"' EXIT
deck=$work/deck.inp
/usr/bin/python3 "$root/bench/make_big_deck.py" "$deck" --cells "${cells[@]}" --stop-after-reading
export FETICON_MESH_CACHE=off

# One run: appends "WALL_SECONDS PEAK_KB EXIT_STATUS" to $work/KIND.txt.
measure() {
  local kind=$1 limit=$2 k=$3
  local status=0
  /usr/bin/time -v -o "$work/time.txt" "$feticon" run "$deck" -o "$work/out-$kind-$k" \
    --set output.plots=false --set output.vtu=false --set memory_limit="$limit" \
    >"$work/stdout.txt" 2>"$work/stderr.txt" || status=$?
  /usr/bin/python3 - "$work/time.txt" "$status" >>"$work/$kind.txt" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
clock = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)", text)
wall = int(clock.group(1) or 0) * 3600 + int(clock.group(2)) * 60 + float(clock.group(3))
peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1))
print(wall, peak, sys.argv[2])
PY
  echo "  $kind run $k: $(tail -1 "$work/$kind.txt") (wall s, peak KB, exit); $(head -c 160 "$work/stderr.txt" | tail -1)"
  rm -rf "$work/out-$kind-$k"
}

for ((k = 1; k <= repeat; ++k)); do
  measure outline 1 "$k"
  measure read 1e12 "$k"
done

/usr/bin/python3 - "$deck" "$work/outline.txt" "$work/read.txt" <<'PY'
import os, re, statistics, sys
deck, outline_file, read_file = sys.argv[1:]
nodes = cells = 0
with open(deck) as f:
    keyword = ""
    for line in f:
        if line.startswith("*"):
            keyword = line[1:].split(",")[0].strip().upper()
        elif keyword == "NODE":
            nodes += 1
        elif keyword == "ELEMENT":
            cells += 1
runs = {name: [tuple(map(float, line.split())) for line in open(path)]
        for name, path in (("outline", outline_file), ("read", read_file))}
for name, rows in runs.items():
    bad = [r for r in rows if r[2] != 1]
    if bad:
        sys.exit(f"deck_read.sh: the {name} run ended with exit {int(bad[0][2])}, not the expected 1")
wall = {name: statistics.median(r[0] for r in rows) for name, rows in runs.items()}
peak = {name: max(r[1] for r in rows) * 1024 for name, rows in runs.items()}
mesh = nodes * 24 + cells * (32 + 4)
read = wall["read"] - wall["outline"]
grown = peak["read"] - peak["outline"]
print(f"deck: {os.path.getsize(deck)} bytes, {nodes} nodes, {cells} C3D8 cells")
print(f"wall time, median of {len(runs['read'])}: outline run {wall['outline']:.2f} s, read run {wall['read']:.2f} s")
print(f"read time (read - outline): {read:.2f} s (target <= 2 s)")
print(f"peak RSS: outline run {peak['outline'] / 2**20:.1f} MiB, read run {peak['read'] / 2**20:.1f} MiB")
print(f"mesh memory (nodes*24 + cells*36): {mesh / 2**20:.1f} MiB")
print(f"read run peak above the outline run's: {grown / 2**20:.1f} MiB = {grown / mesh:.2f} x the mesh "
      f"(whole process {peak['read'] / mesh:.2f} x; target <= 1.5 x)")
PY
