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
