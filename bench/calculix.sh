#!/usr/bin/env bash
# feticon and CalculiX on the identical model (issue 16): exports the problem of the given
# feticon arguments (`feticon export --format calculix`), solves the deck with ccx on 2
# threads and the problem with `feticon run`, --reps times each, alternately, under
# GNU time (ccx writes its .frd and .dat, feticon its results folder with VTU but no PNG
# plots, which have no counterpart in ccx), then bench/calculix_compare.py computes every
# figure with the same code for both and writes CASE/comparison.json. ccx reads its mesh from
# the deck; feticon's reps read theirs from a mesh cache of the case that the export filled
# (docs/usage.md), and one more run, feticon.meshing/, makes it anew (FETICON_MESH_CACHE=off):
# the table gives both times.
#
#   bench/calculix.sh --name hertz-large-60 --reps 3 -- --set hertz.refinement=2.2034
#   bench/calculix.sh --name punch --reps 1 -- examples/flat_punch/problem.yaml
#   bench/calculix.sh --suite                      # the table of docs/benchmarks.md
#   bench/calculix.sh --suite --across 60,120,240  # Hertz sizes (slave elements across 2a);
#                                                  # 240 runs once (minutes per run)
#   bench/calculix.sh --suite --hertz3d 1,1.4      # hertz3d refinements (39k, 97k DOFs), once
#                                                  # each (CalculiX: 1-8 minutes per run)
#   bench/calculix.sh --feticon build-old/feticon ...   # another build (default build/feticon)
#   bench/calculix.sh --out /tmp/cases ...         # case folders elsewhere
#
# Needs Debian's calculix-ccx (installed here if missing, as feticon's dependencies are) and
# GNU time. Results go to bench/results/calculix/NAME/; bench/calculix_table.py makes the table.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
reps=3
name=
suite=false
sizes=60,120
hertz3d=1
threads=2
out=$root/bench/results/calculix
while [[ $# -gt 0 ]]; do
  case $1 in
    --name) name=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --suite) suite=true; shift ;;
    --across) sizes=$2; shift 2 ;;
    --hertz3d) hertz3d=$2; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "bench/calculix.sh: unknown option $1 (see --help)" >&2; exit 1 ;;
  esac
done

need=()
command -v ccx >/dev/null || need+=(calculix-ccx)
[[ -x /usr/bin/time ]] || need+=(time)
if ((${#need[@]})); then
  echo "bench/calculix.sh: installing ${need[*]}"
  sudo_cmd=(); [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
if [[ ! -x $feticon ]]; then
  bash "$root/scripts/install-deps.sh"
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFETICON_BUILD_TESTS=OFF >/dev/null
  cmake --build "$root/build" --target feticon -j "$(nproc)"
fi

# Refinement of the Hertz mesh for N slave elements across 2a: h = 5 mm / r and
# 2a = 136.16 mm, so N = 27.23 r.
across() { /usr/bin/python3 -c "print(round($1 / 27.2312, 4))"; }

if $suite; then
  for n in ${sizes//,/ }; do
    case_reps=$reps; ((n <= 120)) || case_reps=1
    for kind in small large; do
      "$0" --feticon "$feticon" --out "$out" --reps "$case_reps" --name "hertz-$kind-$n" -- \
        --set "hertz.refinement=$(across $n)" --set displacements=$kind
    done
  done
  "$0" --feticon "$feticon" --out "$out" --reps "$reps" --name punch -- "$root/examples/flat_punch/problem.yaml"
  "$0" --feticon "$feticon" --out "$out" --reps "$reps" --name sphere -- "$root/examples/sphere_on_block/problem.yaml"
  "$0" --feticon "$feticon" --out "$out" --reps "$reps" --name sphere-large -- \
    "$root/examples/sphere_on_block/problem.yaml" --set displacements=large
  for r in ${hertz3d//,/ }; do
    for kind in small large; do
      "$0" --feticon "$feticon" --out "$out" --reps 1 --name "hertz3d-$kind-r$r" -- \
        --set problem=hertz3d --set "hertz3d.refinement=$r" --set displacements=$kind
    done
  done
  /usr/bin/python3 "$root/bench/calculix_table.py" "$out"
  exit 0
fi

[[ -n $name ]] || { echo "bench/calculix.sh: give --name NAME (see --help)" >&2; exit 1; }
# Seconds since a bash EPOCHREALTIME stamp, to the microsecond: GNU time's %e has 10 ms steps,
# 12 % of a 0.08 s run (the comparison takes this where a run folder has it).
wall_since() { /usr/bin/python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.6f}')" "$1" "$EPOCHREALTIME"; }
case_dir=$out/$name
rm -rf "$case_dir"
mkdir -p "$case_dir"
printf '%s\n' "$@" > "$case_dir/arguments"
export FETICON_MESH_CACHE=$case_dir/mesh-cache
"$feticon" export "$@" --format calculix --output "$case_dir/deck" 2>&1 | tee "$case_dir/export.log"

# The two alternately, rep by rep: this machine's speed drifts by 10 % over minutes, which runs
# in blocks (all ccx, then all feticon) put on one side of the ratio (docs/benchmarks.md).
for ((i = 1; i <= reps; ++i)); do
  d=$case_dir/ccx.rep$i
  mkdir -p "$d"
  cp "$case_dir/deck/feticon.inp" "$d/"
  echo "bench/calculix.sh: $name: ccx run $i of $reps"
  start=$EPOCHREALTIME
  (cd "$d" && OMP_NUM_THREADS=$threads CCX_NPROC_EQUATION_SOLVER=$threads \
     /usr/bin/time -f '%e %M %P' -o time ccx -i feticon > stdout 2>&1) ||
    echo "bench/calculix.sh: $name: ccx failed, see $d/stdout" >&2
  wall_since "$start" > "$d/wall"
  rm -f "$d/feticon.inp"
  d=$case_dir/feticon.rep$i
  echo "bench/calculix.sh: $name: feticon run $i of $reps"
  mkdir -p "$d"
  start=$EPOCHREALTIME
  /usr/bin/time -f '%e %M %P' -o "$case_dir/time.tmp" \
    "$feticon" run "$@" --set output.plots=false --quiet --output "$d" ||
    echo "bench/calculix.sh: $name: feticon failed" >&2
  wall_since "$start" > "$case_dir/wall.tmp"
  mv "$case_dir/time.tmp" "$d/time"
  mv "$case_dir/wall.tmp" "$d/wall"
done
d=$case_dir/feticon.meshing
echo "bench/calculix.sh: $name: feticon run making its mesh"
mkdir -p "$d"
FETICON_MESH_CACHE=off /usr/bin/time -f '%e %M %P' -o "$case_dir/time.tmp" \
  "$feticon" run "$@" --set output.plots=false --quiet --output "$d" ||
  echo "bench/calculix.sh: $name: feticon failed" >&2
mv "$case_dir/time.tmp" "$d/time"
/usr/bin/python3 "$root/bench/calculix_compare.py" "$case_dir" > /dev/null
echo "bench/calculix.sh: $name: $case_dir/comparison.json"
