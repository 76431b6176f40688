#!/usr/bin/env bash
# A deck byte that is not UTF-8 echoed in a warning (an unknown *CONTACT PRINT variable with a
# 0xFF byte, found by the deck fuzzer) ends the run with its results and a summary.json that
# parses, the byte as U+FFFD; before, the completed run failed writing the summary (exit 2).
# Usage: deck_non_utf8.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sed 's/^CELS$/CE\xffLS/' "$source_dir/tests/data/calculix/contactenergy.inp" >"$work/bytes.inp"
grep -q $'CE\xffLS' "$work/bytes.inp"
"$feticon" run -q "$work/bytes.inp" --output "$work/out" --set output.plots=false 2>/dev/null
/usr/bin/python3 - "$work/out/summary.json" <<'PY'
import json
import sys

s = json.load(open(sys.argv[1], encoding="utf-8"))
assert s["completed"], s
assert any("CE\ufffdLS" in w for w in s["warnings"]), s["warnings"]
print("summary.json parses; the byte is U+FFFD in its warning")
PY
