#!/usr/bin/env bash
# Reproduces the seed's figures on the Hertz benchmark and prints the tables behind them:
#   fig2a_primal_penalty.png  five primal penalties eps_n against McEwen (seed Fig. 2a)
#   fig2b_dual_penalty.png    dual penalty for rho = 1..1e4 and SMALBE-M (seed Fig. 2b)
#   fig3a_inner_iterations.png MPRGP steps per outer iteration, large displacements (Fig. 3a)
#   fig3b_rho_sweep.png       MPRGP steps against rho, large displacements (Fig. 3b)
# Usage: bash scripts/seed-figures.sh [OUTPUT_DIR] [extra --set options...]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/results-figures}"
shift || true
bash "$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFETICON_BUILD_TESTS=OFF >/dev/null
cmake --build "$root/build" --target feticon -j "$(nproc)"
feticon="$root/build/feticon"
mkdir -p "$out"
run() { local dir="$1"; shift; "$feticon" run -q --overwrite --output "$out/$dir" "$@" >/dev/null || echo "run $dir failed"; }

small=(--set displacements=small)
for eps in 0.0001 0.001 0.01 0.1 1; do run "primal_$eps" "${small[@]}" --set method=primal_penalty --set eps_n=$eps "$@"; done
for rho in 1 10 100 1000 10000; do run "dual_$rho" "${small[@]}" --set method=dual_penalty --set rho=$rho "$@"; done
for rho in 1 10 100 1000 10000; do run "smalbe_$rho" "${small[@]}" --set method=smalbe --set rho=$rho "$@"; done
# The seed's large-displacement runs: its load in two steps (feticon's default is one).
large=(--set displacements=large --set load_steps=2)
for rho in 1 10 100 1000 10000; do
  run "large_dual_$rho" "${large[@]}" --set method=dual_penalty --set rho=$rho "$@"
  run "large_smalbe_$rho" "${large[@]}" --set method=smalbe --set rho=$rho "$@"
done
/usr/bin/python3 "$root/scripts/plot_hertz.py" --figure "$out/fig2a_primal_penalty.png" \
  --title "Primal penalty (seed Fig. 2a)" "$out"/primal_*
/usr/bin/python3 "$root/scripts/plot_hertz.py" --figure "$out/fig2b_dual_penalty.png" \
  --title "Dual penalty and SMALBE-M (seed Fig. 2b)" "$out"/dual_* "$out/smalbe_1"
/usr/bin/python3 "$root/scripts/plot_iterations.py" "$out"
