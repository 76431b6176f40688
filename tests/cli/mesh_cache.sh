#!/usr/bin/env bash
# CLI test of the mesh cache (src/mesh/mesh_cache.hpp) and of the Gmsh module loaded on first
# use (src/mesh/gmsh_module.hpp). References: the run that made its mesh (a run with the cached
# mesh must give the same contact pressures, byte for byte) and the process's own library map.
# Usage: mesh_cache.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export FETICON_MESH_CACHE="$work/cache"
run() { "$feticon" run -q --overwrite --set hertz.refinement=0.5 --set subdomains=4 \
          --set displacements=small --set output.plots=false --set output.vtu=false "$@"; }
from_cache() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['mesh_from_cache'])" "$1/summary.json"; }

# 1. The graded Hertz mesh: made and stored, then read back; the same answer either way.
run --output "$work/made"
run --output "$work/cached"
[[ $(from_cache "$work/made") == False && $(from_cache "$work/cached") == True ]] \
  || { echo "expected made then cached: $(from_cache "$work/made") $(from_cache "$work/cached")"; exit 1; }
cmp "$work/made/contact_pressure.csv" "$work/cached/contact_pressure.csv"
[[ $(ls "$work/cache" | wc -l) -eq 1 ]] || { echo "expected one cache entry"; ls "$work/cache"; exit 1; }

# 2. Another mesh parameter is another entry; FETICON_MESH_CACHE=off stores nothing.
run --output "$work/other" --set hertz.growth_ratio=1.2
[[ $(from_cache "$work/other") == False && $(ls "$work/cache" | wc -l) -eq 2 ]] || { echo "growth_ratio must miss"; exit 1; }
FETICON_MESH_CACHE=off run --output "$work/off"
[[ $(from_cache "$work/off") == False && $(ls "$work/cache" | wc -l) -eq 2 ]] || { echo "off must neither read nor store"; exit 1; }

# 3. A damaged entry is a miss that is rebuilt, not an error.
for f in "$work"/cache/*.mesh; do head -c 100 "$f" > "$f.cut" && mv "$f.cut" "$f"; done
run --output "$work/rebuilt"
[[ $(from_cache "$work/rebuilt") == False ]] || { echo "a truncated entry was read"; exit 1; }
cmp "$work/made/contact_pressure.csv" "$work/rebuilt/contact_pressure.csv"

# 4. A cache that cannot be written (a file where its folder should be) costs one warning line
#    naming it (on stderr and in summary.json), not the run.
echo "not a folder" > "$work/blocked"
FETICON_MESH_CACHE="$work/blocked" run --output "$work/blocked_run" 2> "$work/stderr"
[[ $(wc -l < "$work/stderr") -eq 1 ]] && grep -q "mesh cache: .*$work/blocked" "$work/stderr" \
  || { echo "expected one warning naming the cache folder:"; cat "$work/stderr"; exit 1; }
cmp "$work/made/contact_pressure.csv" "$work/blocked_run/contact_pressure.csv"
/usr/bin/python3 -c "import json,sys; w=json.load(open(sys.argv[1]))['warnings']; sys.exit(not any('mesh cache' in x for x in w))" \
  "$work/blocked_run/summary.json" || { echo "summary.json does not list the mesh cache warning"; exit 1; }

# 5. Gmsh is loaded only when a mesh is made: not for the mapped (tensor) mesh nor a cached
#    one (the dynamic linker's trace of the files it opens).
libs_of() { LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -c "file=libgmsh" || true; }
[[ $(libs_of "$feticon" run -q --overwrite --output "$work/t" --set hertz.mesh=tensor --set hertz.refinement=0.5 \
       --set subdomains=4 --set displacements=small --set output.plots=false) -eq 0 ]] || { echo "tensor mesh loaded Gmsh"; exit 1; }
[[ $(libs_of "$feticon" run -q --overwrite --output "$work/c" --set hertz.refinement=0.5 --set subdomains=4 \
       --set displacements=small --set output.plots=false) -eq 0 ]] || { echo "cached mesh loaded Gmsh"; exit 1; }
[[ $(FETICON_MESH_CACHE=off libs_of "$feticon" run -q --overwrite --output "$work/g" --set hertz.refinement=0.5 \
       --set subdomains=4 --set displacements=small --set output.plots=false) -gt 0 ]] || { echo "Gmsh not loaded to mesh"; exit 1; }
echo "mesh cache: ok"
