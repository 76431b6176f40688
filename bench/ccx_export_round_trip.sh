#!/usr/bin/env bash
# Every deck of Debian's calculix-ccx-test with a *CONTACT PAIR that feticon runs, through
# `feticon export` and back: the deck's run against the run of the deck the export writes of it
# (the same subdomains, contact.law=deck), max |u - u'| over max |u| of their last increment, or
# the one line the export refuses it with. What the export drops or changes shows here (the
# *EQUATIONs, ADJUST, a tension sigma_inf were found so: docs/usage.md, "feticon export").
# Writes a markdown table (deck | increments | difference or refusal) to stdout.
#
#   bench/ccx_export_round_trip.sh                     # build/feticon
#   bench/ccx_export_round_trip.sh --feticon build/feticon --timeout 300
# Needs the package calculix-ccx-test (apt-get install calculix-ccx-test).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
timeout_s=600
while [[ $# -gt 0 ]]; do
  case $1 in
    --feticon) feticon=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    *) echo "bench/ccx_export_round_trip.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
examples=/usr/share/doc/calculix-ccx-test/examples/test
[[ -d $examples ]] || { echo "bench/ccx_export_round_trip.sh: install calculix-ccx-test" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
settings=(--set output.plots=false --set contact.law=deck)
echo "| deck | increments | exported deck's run vs the deck's |"
echo "|---|---|---|"
for path in "$examples"/*.inp "$examples"/*.inp.gz; do
  name=$(basename "$path" .gz)
  name=${name%.inp}
  deck="$work/$name.inp"
  if [[ $path == *.gz ]]; then zcat "$path" > "$deck"; else cp "$path" "$deck"; fi
  grep -qi '^\*CONTACT PAIR' "$deck" || continue
  timeout "$timeout_s" "$feticon" run -q "$deck" -o "$work/$name" "${settings[@]}" > /dev/null 2>&1 || continue
  if ! "$feticon" export "$deck" --format calculix --overclosure 0 -o "$work/$name-deck" > "$work/$name.log" 2>&1; then
    echo "| $name | | refused: $(tail -1 "$work/$name.log") |"
    continue
  fi
  subdomains=$(/usr/bin/python3 -c "import json; print(json.load(open('$work/$name/summary.json'))['subdomains'])")
  if ! timeout "$timeout_s" "$feticon" run -q "$work/$name-deck/feticon.inp" -o "$work/$name-back" "${settings[@]}" \
    --set subdomains="$subdomains" > /dev/null 2>&1; then
    echo "| $name | | the exported deck's run failed |"
    continue
  fi
  /usr/bin/python3 - "$work/$name" "$work/$name-back" "$name" "$root/tests/tools" <<'PY'
import glob
import sys

import numpy

a, b, name, tools = sys.argv[1:]
sys.path.insert(0, tools)
import read_vtu

steps_a, steps_b = (sorted(glob.glob(d + "/step_*.vtu")) for d in (a, b))
u_a, u_b = (read_vtu.point_data(s[-1])["displacement"] for s in (steps_a, steps_b))
difference = numpy.abs(u_a - u_b).max() / max(numpy.abs(u_a).max(), 1e-300)
print(f"| {name} | {len(steps_a)} and {len(steps_b)} | {difference:.2e} |")
PY
done
