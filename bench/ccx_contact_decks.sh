#!/usr/bin/env bash
# Every deck of Debian's calculix-ccx-test with a *CONTACT PAIR through `feticon run`: whether
# it runs (exit 0; converged or not, from summary.json) or is refused, and the one line that
# says why; for a deck that runs and whose DECK.dat.ref prints displacements, how far its last
# ones are from CalculiX's (max |du| over max |u|, tests/tools/calculix_reference_agreement.py;
# "(frd)": from its .frd.ref; "(dat p)": contact pressures, where the .dat.ref prints no
# displacement, not counted in the tally).
# Writes a markdown table (deck | verdict | vs CalculiX | line) to stdout; the tallies at the end
# (decks within 2 % of max |u|).
#
#   bench/ccx_contact_decks.sh                         # build/feticon
#   bench/ccx_contact_decks.sh --feticon build/feticon --timeout 300 --set contact.law=deck
# Needs the package calculix-ccx-test (apt-get install calculix-ccx-test).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
feticon=$root/build/feticon
timeout_s=600
settings=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --feticon) feticon=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --set) settings+=(--set "$2"); shift 2 ;;
    *) echo "bench/ccx_contact_decks.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
examples=/usr/share/doc/calculix-ccx-test/examples/test
[[ -d $examples ]] || { echo "bench/ccx_contact_decks.sh: install calculix-ccx-test" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=0 refused=0 total=0 agree=0
echo "| deck | verdict | vs CalculiX | feticon's line |"
echo "|---|---|---|---|"
for path in "$examples"/*.inp "$examples"/*.inp.gz; do
  name=$(basename "$path" .gz)
  if [[ $path == *.gz ]]; then zcat "$path" > "$work/$name"; else cp "$path" "$work/$name"; fi
  grep -qi '^\*CONTACT PAIR' "$work/$name" || continue
  total=$((total + 1))
  out="$work/${name%.inp}"
  versus=""
  if timeout "$timeout_s" "$feticon" run -q "$work/$name" -o "$out" --set output.plots=false --set output.vtu=false \
    "${settings[@]}" > /dev/null 2> "$work/err"; then
    runs=$((runs + 1))
    verdict=$(/usr/bin/python3 -c "import json; s = json.load(open('$out/summary.json'))
print('runs, converged' if s['converged'] else 'runs, not converged')")
    line="$(grep -c . "$work/err" || true) warning line(s)"
    # The .dat.ref where it prints displacements, else the .frd.ref.
    for kind in dat frd; do
      reference=$(ls "$examples/${name%.inp}".$kind.ref* 2> /dev/null | head -n 1 || true)
      [[ -n $reference && -s $out/${name%.inp}.$kind ]] || continue
      if [[ $reference == *.gz ]]; then zcat "$reference" > "$work/ref.$kind.ref"; else cp "$reference" "$work/ref.$kind.ref"; fi
      versus=$(/usr/bin/python3 "$root/tests/tools/calculix_reference_agreement.py" "$work/$name" "$work/ref.$kind.ref" \
        "$out" 2> /dev/null | /usr/bin/python3 -c "import json, sys; f = json.load(sys.stdin)
print(f'{f[\"relative\"]:.2e} ($kind{\" p\" if f[\"quantity\"] == \"pressure\" else \"\"})' if f['nodes'] else '')" \
        2> /dev/null || true)
      [[ -z $versus ]] || break
    done
    if [[ -n $versus && $versus != *" p)" ]] && /usr/bin/python3 -c "import sys; sys.exit(0 if float('${versus%% *}') <= 0.02 else 1)"; then
      agree=$((agree + 1))
    fi
  else
    rc=$?
    refused=$((refused + 1))
    verdict=$([[ $rc -ge 124 ]] && echo "timeout/signal $rc" || echo refused)
    line=$(grep -m1 'error' "$work/err" | sed "s|$work/||g; s/|/\\\\|/g" | cut -c1-220)
  fi
  echo "| $name | $verdict | $versus | $line |"
done
echo
echo "$runs of $total run, $refused refused; $agree within 2 % of max |u| of CalculiX's reference (.dat.ref, else .frd.ref)"
