#!/usr/bin/env bash
# First yield under a Hertz sphere (issue 66's acceptance; docs/materials.md): the hertz3d
# built-in problem (sphere R = 50 mm on a block, 20 kN, steel, small displacements) exported as
# a deck with *EL PRINT S; feticon's largest von Mises stress over the block's integration points
# gives the first-yield p0 / Y and its depth (Johnson: 1.60 Y at 0.48 a, nu = 0.3; the Hertz
# field's exact on-axis values 1.6128 Y at 0.4809 a). Then the block made perfectly plastic
# (*PLASTIC) with Y 3 % above and 3 % below that stress: no point may yield in the first, the
# second yields around the depth found.
# With --calculix, also the block at Y = 0.8 of that stress (above first yield), one increment,
# in feticon and in CalculiX on the identical deck: the yielded points and the contact pressure
# profile of both (bench/hertz_plastic_profile.py), and their wall times; then the elastic
# block's profiles in both, for what the contact discretizations differ by without yield.
# Usage: bench/hertz_first_yield.sh [FETICON] [REFINEMENT] [--calculix]
set -euo pipefail
feticon="$(realpath "${1:-build/feticon}")"
refinement="${2:-1}"
calculix="${3:-}"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
"$feticon" export --set problem=hertz3d --set displacements=small --set hertz3d.refinement="$refinement" \
  --format calculix -o deck | tail -1
sed -i 's/^\*END STEP$/*EL PRINT, ELSET=B_block\nS\n*END STEP/' deck/feticon.inp
read -r a p0 < <(/usr/bin/python3 -c "
import math
P, R, E_star = 2e4, 0.05, 2e11 / (2 * (1 - 0.3**2))
a = (3 * P * R / (4 * E_star)) ** (1 / 3)
print(a, 3 * P / (2 * math.pi * a * a))")
echo "Hertz: a = $a m, p0 = $p0 Pa"
"$feticon" run -q deck/feticon.inp --output elastic --set output.plots=false 2>/dev/null
/usr/bin/python3 "$here/hertz_first_yield.py" deck/feticon.inp elastic/feticon.dat "$a" "$p0" | tee elastic.txt
mises="$(sed -n 's/^largest von Mises \(\S*\) Pa.*/\1/p' elastic.txt)"
for factor in 1.03 0.97; do
  yield_stress="$(/usr/bin/python3 -c "print($mises * $factor)")"
  sed "s/^\*SOLID SECTION, ELSET=B_block, MATERIAL=M_block$/*PLASTIC\n$yield_stress, 0\n&/;
       s/^\*EL PRINT, ELSET=B_block$/*EL PRINT, ELSET=B_block\nPEEQ\n&/" deck/feticon.inp >"y$factor.inp"
  start=$(date +%s.%N)
  "$feticon" run -q "y$factor.inp" --output "plastic$factor" --set output.plots=false 2>/dev/null
  echo "Y = $factor x that stress: $(/usr/bin/python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')") s"
  /usr/bin/python3 "$here/hertz_first_yield.py" "y$factor.inp" "plastic$factor/y$factor.dat" "$a" "$p0" | tail -2
done

[[ $calculix == --calculix ]] || exit 0
yield_stress="$(/usr/bin/python3 -c "print($mises * 0.8)")"
sed "s/^\*SOLID SECTION, ELSET=B_block, MATERIAL=M_block$/*PLASTIC\n$yield_stress, 0\n&/;
     s/^\*EL PRINT, ELSET=B_block$/*EL PRINT, ELSET=B_block\nPEEQ\n&/" deck/feticon.inp > above.inp
mkdir -p ccx && cp above.inp ccx/
start=$(date +%s.%N)
"$feticon" run -q above.inp --output above --set output.plots=false 2>/dev/null
echo "feticon, Y = 0.8 x that stress: $(/usr/bin/python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')") s"
/usr/bin/python3 "$here/hertz_first_yield.py" above.inp above/above.dat "$a" "$p0" | tail -2
start=$(date +%s.%N)
(cd ccx && OMP_NUM_THREADS=2 ccx -i above > ccx.log 2>&1)
echo "CalculiX, the same deck: $(/usr/bin/python3 -c "print(f'{$(date +%s.%N) - $start:.2f}')") s"
/usr/bin/python3 "$here/hertz_first_yield.py" above.inp ccx/above.dat "$a" "$p0" | tail -2
echo "pressure profiles above first yield:"
/usr/bin/python3 "$here/hertz_plastic_profile.py" above.inp above/above.frd ccx/above.frd "$a" "$p0"
# The same comparison of the elastic run: what the two codes' contact discretizations differ by
# without plasticity.
cp deck/feticon.inp ccx/elastic.inp
(cd ccx && OMP_NUM_THREADS=2 ccx -i elastic > elastic.log 2>&1)
echo "pressure profiles of the elastic block:"
/usr/bin/python3 "$here/hertz_plastic_profile.py" deck/feticon.inp elastic/feticon.frd ccx/elastic.frd "$a" "$p0"
/usr/bin/python3 "$here/hertz_plastic_profile.py" above.inp above/above.frd ccx/above.frd "$a" "$p0" \
  elastic/feticon.frd ccx/elastic.frd | tail -1
