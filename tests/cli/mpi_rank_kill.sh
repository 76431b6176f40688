#!/usr/bin/env bash
# A rank that dies (issue 36): rank 1 of a 2-rank run is killed with SIGKILL in the middle of
# the solve, where rank 0 waits for it in a collective. The run must end within 30 s with a
# non-zero status and a line naming the lost rank, instead of rank 0 hanging forever.
# Reference: Open MPI's job control (mpirun ends the job when one of its processes dies and
# reports "process rank N ... exited on signal 9").
# Usage: mpi_rank_kill.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
mpirun_pid=
cleanup() {
  [[ -z $mpirun_pid ]] || kill -9 "$mpirun_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_mpi_yield_when_idle=1
export OPENBLAS_NUM_THREADS=1
[[ -z ${FETICON_SANITIZED:-} ]] || export LSAN_OPTIONS="${LSAN_OPTIONS:-}:detect_leaks=0"

# Hertz with many small load steps: a minute of outer iterations on 2 ranks, killed after the first.
mpirun --oversubscribe -np 2 "$feticon" run --output "$work/run" --set subdomains=8 --set load_steps=200 \
  --set output.vtu=false --set output.plots=false >"$work/out" 2>"$work/err" &
mpirun_pid=$!

# The first outer iteration's progress line: the ranks are in the solve.
for _ in $(seq 1 600); do
  grep -q "outer" "$work/out" 2>/dev/null && break
  kill -0 "$mpirun_pid" 2>/dev/null || { cat "$work/out" "$work/err"; echo "the run ended before the kill"; exit 1; }
  sleep 0.1
done
grep -q "outer" "$work/out" || { cat "$work/out" "$work/err"; echo "no outer iteration within 60 s"; exit 1; }

# Rank 1: the feticon process whose environment says OMPI_COMM_WORLD_RANK=1.
victim=
for pid in $(pgrep -f "$feticon run --output $work/run"); do
  if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1"; then
    victim=$pid
  fi
done
[[ -n $victim ]] || { echo "rank 1's process not found"; exit 1; }
kill -9 "$victim"
killed_at=$(date +%s%N)

status=0
for _ in $(seq 1 300); do
  kill -0 "$mpirun_pid" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$mpirun_pid" 2>/dev/null; then
  echo "the run still runs 30 s after rank 1 was killed"; exit 1
fi
wait "$mpirun_pid" || status=$?
mpirun_pid=
elapsed_ms=$((($(date +%s%N) - killed_at) / 1000000))
echo "ended $elapsed_ms ms after the kill with status $status"
[[ $status -ne 0 ]] || { echo "a run that lost rank 1 exited 0"; exit 1; }
grep -Eiq "rank 1\b" "$work/err" "$work/out" || { cat "$work/err"; echo "no line names the lost rank 1"; exit 1; }
grep -Ei "rank 1\b" "$work/err" "$work/out" | head -2
