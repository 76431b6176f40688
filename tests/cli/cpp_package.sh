#!/usr/bin/env bash
# feticon as a C++ library (issue 67, item 3): `cmake --install` of the build tree into a
# scratch prefix, examples/cpp_library configured with find_package(feticon) against it, built
# and run; its Hertz figures must be the executable's (the same library call, so the reference
# is `feticon run` of the same problem). The installed Python module imports without the
# build tree.
# Usage: cpp_package.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$(realpath "$1")"
src="$(realpath "$2")"
build="$(dirname "$feticon")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$src/examples/cpp_library" -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/example" >/dev/null
"$work/example/hertz_example" >"$work/example.log"
cat "$work/example.log"
"$feticon" run -q --output "$work/cli" --set hertz.line_load=2e8
/usr/bin/python3 - "$work/cli/summary.json" "$work/example.log" <<'PY'
import json
import sys

cli = json.load(open(sys.argv[1]))
line = [l for l in open(sys.argv[2]) if l.startswith("Q = 2e8")][0]
p_peak = float(line.split("p_peak ")[1].split(" Pa")[0])
assert abs(p_peak / cli["hertz"]["p_peak_computed"] - 1) < 1e-6, (p_peak, cli["hertz"]["p_peak_computed"])
iterations = int(line.split(", ")[-1].split(" MPRGP")[0])
assert iterations == cli["qp"]["iterations"], (iterations, cli["qp"]["iterations"])
PY
if [[ -f "$build/python/feticon/__init__.py" ]]; then
  site="$(ls -d "$work"/prefix/lib/python3*/dist-packages)"
  PYTHONPATH="$site" /usr/bin/python3 -c "import feticon, os; assert feticon.__file__.startswith('$work'), feticon.__file__"
fi
echo "cpp package: the installed library runs the Hertz benchmark as the executable does"
