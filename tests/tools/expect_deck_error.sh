# Sourced by tests/cli scripts (not run by itself): expect_error NAME PATTERN runs
# "$feticon" on the mutated deck "$work/NAME.inp" and exits the script unless the run fails with
# one line matching PATTERN (grep; the log may end with an empty line).
expect_error() {
  local name="$1" pattern="$2"
  if "$feticon" run -q "$work/$name.inp" --output "$work/bad_$name" >"$work/$name.log" 2>&1; then
    echo "$name: the run did not fail"
    exit 1
  fi
  grep -q "$pattern" "$work/$name.log" || { echo "$name: no '$pattern' in:"; cat "$work/$name.log"; exit 1; }
  [ "$(grep -c . "$work/$name.log")" -le 2 ] || { echo "$name: more than one line:"; cat "$work/$name.log"; exit 1; }
}

# expect_export_error FILE NAME PATTERN: `feticon export FILE --format calculix` fails with one
# line on stderr matching PATTERN (kept in "$work/NAME.err"), which the script then echoes.
expect_export_error() {
  local file="$1" name="$2" pattern="$3"
  if "$feticon" export "$file" --format calculix -o "$work/$name-deck" >/dev/null 2>"$work/$name.err"; then
    echo "$name: exported"
    exit 1
  fi
  [ "$(wc -l <"$work/$name.err")" -eq 1 ] && grep -q "$pattern" "$work/$name.err" ||
    { echo "$name: not one line matching '$pattern':"; cat "$work/$name.err"; exit 1; }
  echo "bad input: $(cat "$work/$name.err")"
}
