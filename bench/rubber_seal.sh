#!/usr/bin/env bash
# The rubber seal of issue 66 ("a rubber cylinder or seal compressed 30 % between rigid-ish plates
# with large displacements, against CalculiX on the same deck"): examples/rubber_seal (an O-ring
# section, Neo-Hooke, plane strain, a quarter by symmetry) as the deck `feticon export` writes,
# run by CalculiX 2.20 (ccx, 2 threads) and by feticon one after the other --reps times each:
# the plate's force at every increment of both (its total reaction in the .dat), their largest
# difference over the curve, wall time and peak memory (medians).
# With --locking, the volumetric locking study: the same problem at K_0 / mu_0 = 50, 500 and 5000
# (nu_0 = 0.490, 0.499, 0.4999) on the quad4 mesh, the quad4 mesh halved (gmsh -clscale 0.5) and
# the quad8 mesh (gmsh -order 2, serendipity): the plate's final force and the run's wall time.
#
# --set KEY=VALUE goes to feticon's runs (--locking --set hyperelastic.fbar=true: F-bar).
#
#   bench/rubber_seal.sh [--reps N] [--feticon build/feticon] [--locking] [--set KEY=VALUE ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
reps=3
locking=false
extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --feticon) feticon=$2; shift 2 ;;
    --locking) locking=true; shift ;;
    --set) extra+=(--set "$2"); shift 2 ;;
    *) echo "usage: $0 [--reps N] [--feticon PATH] [--locking] [--set KEY=VALUE ...]" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
example=$root/examples/rubber_seal
options=(--overwrite --set output.plots=false --set output.vtu=false "${extra[@]}")
if $locking; then
  echo "mesh           K0/mu0  plate force (N)  wall (s)"
  for mesh in quad4 quad4_half quad8; do
    case $mesh in
      quad4) gmsh_options=() ;;
      quad4_half) gmsh_options=(-clscale 0.5) ;;
      quad8) gmsh_options=(-order 2 -string "Mesh.SecondOrderIncomplete=1;") ;;
    esac
    gmsh -2 -format msh41 "${gmsh_options[@]}" "$example/rubber_seal.geo" -o "$work/$mesh.msh" > /dev/null
    for d1 in 4e-8 4e-9 4e-10; do
      sed -e "s|rubber_seal.msh|$mesh.msh|" -e "s|d1: 4e-8|d1: $d1|" "$example/problem.yaml" > "$work/problem.yaml"
      /usr/bin/time -f "%e" -o "$work/time" "$feticon" run "$work/problem.yaml" -o "$work/run" "${options[@]}" \
        > "$work/log" 2>&1
      force=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['contact']['total_normal_force'])" \
        "$work/run/summary.json")
      printf "%-14s %-7s %-16.6g %s\n" "$mesh" "$(/usr/bin/python3 -c "print(round(2 / $d1 / 1e6))")" "$force" \
        "$(cat "$work/time")"
    done
  done
  exit 0
fi
"$feticon" export "$example/problem.yaml" --format calculix -o "$work/deck" > /dev/null
for ((r = 1; r <= reps; ++r)); do
  (cd "$work/deck" && OMP_NUM_THREADS=2 /usr/bin/time -f "%e %M" -o "ccx.$r.time" ccx -i feticon > ccx.log 2>&1)
  /usr/bin/time -f "%e %M" -o "$work/deck/feticon.$r.time" "$feticon" run "$work/deck/feticon.inp" \
    -o "$work/run" "${options[@]}" > /dev/null 2>&1
done
/usr/bin/python3 - "$work" "$reps" "$root" <<'PY'
import statistics, sys
work, reps, root = sys.argv[1], int(sys.argv[2]), sys.argv[3]
sys.path.insert(0, root + "/tests/tools")
from calculix_dat import parse_dat
curves = {}
for code, dat in (("ccx", work + "/deck/feticon.dat"), ("feticon", work + "/run/feticon.dat")):
    curves[code] = {round(b["time"], 9): -b["rows"][0][1] for b in parse_dat(dat)["blocks"]
                    if b["kind"] == "total force" and b["set"] == "N_PLATE_TOP"}
final = curves["ccx"][1.0]
common = sorted(set(curves["ccx"]) & set(curves["feticon"]))
print("time    CalculiX (N)   feticon (N)    difference / final force")
for t in common:
    a, b = curves["ccx"][t], curves["feticon"][t]
    print(f"{t:<7.4g} {a:<14.7g} {b:<14.7g} {(b - a) / final:+.1e}")
worst = max(abs(curves["feticon"][t] - curves["ccx"][t]) for t in common) / final
print(f"largest difference over {len(common)} common increments: {worst:.1e} of the final force")
for code in ("ccx", "feticon"):
    times = [open(f"{work}/deck/{code}.{r}.time").read().split() for r in range(1, reps + 1)]
    wall = statistics.median(float(t[0]) for t in times)
    memory = statistics.median(int(t[1]) for t in times) / 2**10
    print(f"{code:8s} wall {wall:.2f} s, peak memory {memory:.0f} MiB (medians of {reps})")
PY
