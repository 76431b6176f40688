#!/usr/bin/env bash
# The memory guard under a cgroup memory limit (issue 36): a run whose estimate exceeds the room
# under its cgroup's limit is refused before it allocates, with a line naming the limit's file;
# a run that fits the same limit runs.
# The limit is given as the kernel lays it out (v2 memory.max, v1 memory.limit_in_bytes, at the
# process's cgroup path from /proc/self/cgroup) in a private mount namespace whose
# /sys/fs/cgroup is a tmpfs of this test's making (unshare -m): no real cgroup is changed, and
# the kernel does not enforce the limit here, so the test checks the guard, not the kernel.
# Skipped (77) where that namespace cannot be made (not root, no unshare).
# Usage: cgroup_limit.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
if [[ $(id -u) != 0 ]] || ! command -v unshare > /dev/null || ! unshare -m true 2> /dev/null; then
  echo "skipped: needs root and unshare -m for a private /sys/fs/cgroup"
  exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

limit=$((150 * 1000 * 1000)) usage=$((20 * 1000 * 1000)) # room 130 MB = 124 MiB

# under_limit NAME ARGS...: feticon run ARGS with the fake limit; exit status, peak RSS (KB)
# and stderr in $work/NAME.{status,rss,err}.
under_limit() {
  local name=$1
  shift
  unshare -m bash -s "$limit" "$usage" "$work/$name" "$feticon" "$@" <<'SH'
set -euo pipefail
limit=$1 usage=$2 out=$3
shift 3
mount -t tmpfs feticon-test-cgroup /sys/fs/cgroup
while IFS=: read -r id controllers path; do
  if [[ $id == 0 && -z $controllers ]]; then
    mkdir -p "/sys/fs/cgroup$path"
    echo "$limit" > "/sys/fs/cgroup$path/memory.max"
    echo "$usage" > "/sys/fs/cgroup$path/memory.current"
  elif [[ ,$controllers, == *,memory,* ]]; then
    mkdir -p "/sys/fs/cgroup/memory$path"
    echo "$limit" > "/sys/fs/cgroup/memory$path/memory.limit_in_bytes"
    echo "$usage" > "/sys/fs/cgroup/memory$path/memory.usage_in_bytes"
  fi
done < /proc/self/cgroup
/usr/bin/python3 - "$out" "$@" <<'PY'
import resource, subprocess, sys
out, command = sys.argv[1], sys.argv[2:]
with open(out + ".err", "w") as err:
    status = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=err).returncode
open(out + ".status", "w").write(str(status))
open(out + ".rss", "w").write(str(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss))
PY
SH
}

failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# hertz3d at refinement 1 in 8 subdomains with the Dirichlet preconditioner: about 250 MiB,
# over the 124 MiB of room (subdomains = auto would take more, smaller subdomains; it cannot
# fit them either: see the second case).
under_limit big run -q --output "$work/big" --set problem=hertz3d --set displacements=small --set subdomains=8 \
  --set qp.preconditioner=dirichlet
[[ $(cat "$work/big.status") != 0 ]] || fail "a run over the cgroup's room was not refused"
grep -q "needs about .* MiB.*the cgroup limit /sys/fs/cgroup/.*less its usage.*raise the cgroup's memory limit" \
  "$work/big.err" || fail "the refusal does not name the cgroup limit: $(cat "$work/big.err")"
[[ $(wc -l < "$work/big.err") -eq 1 ]] || fail "the refusal is not one line: $(cat "$work/big.err")"
[[ ! -e $work/big ]] || fail "the refused run made its output folder"
# Refused before it allocates: the process stays far below the limit (64 MiB of libraries).
(($(cat "$work/big.rss") * 1024 < limit)) || fail "the refused run peaked at $(cat "$work/big.rss") KB"

# With subdomains = auto the count is raised towards the room, but not below subdomains of
# 1000 DOFs (39 here), where the estimate is still over it: refused as well.
under_limit auto run -q --output "$work/auto" --set problem=hertz3d --set displacements=small
[[ $(cat "$work/auto.status") != 0 ]] || fail "an auto run over the cgroup's room was not refused"
grep -q "in 39 subdomains" "$work/auto.err" || fail "the auto run was not raised to 39 subdomains: $(cat "$work/auto.err")"

# A small Hertz run fits the same room and runs.
under_limit small run -q --output "$work/small" --set hertz.refinement=0.5 --set displacements=small \
  --set output.vtu=false --set output.plots=false
[[ $(cat "$work/small.status") == 0 ]] || fail "a run within the cgroup's room failed: $(cat "$work/small.err")"

cat "$work/big.err"
((failures == 0)) || exit 1
echo "cgroup_limit: ok"
