#!/usr/bin/env bash
# Magnitudes far from steel's (issue 36): the Hertz problem with moduli of 1e-30 and 1e30 Pa
# and line loads of 1e-20 and 1e30 N/m, small and large displacements. Each run must either
# solve, with the contact force equal to the applied load to 1e-6 (summary.json: an
# equilibrium the solver does not get told), or end in one line naming the cause; within 60 s
# and 1 GB; never a signal, a hang, or a non-finite result. Reference: the load itself.
# Usage: magnitudes.sh FETICON SOURCE_DIR
set -euo pipefail
feticon="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 - "$feticon" "$work" <<'PY'
import json, math, os, resource, subprocess, sys, time
feticon, work = sys.argv[1:]
cases = {"E 1e-30": ["material.young=1e-30", "hertz.block_young=1e-30"],
         "E 1e30": ["material.young=1e30", "hertz.block_young=1e30"],
         "load 1e-20": ["hertz.line_load=1e-20"],
         "load 1e30": ["hertz.line_load=1e30"]}
failed = []
for kinematics in ("small", "large"):
    for name, settings in cases.items():
        out = os.path.join(work, f"{kinematics}-{name.replace(' ', '_')}")
        command = [feticon, "run", "-q", "--output", out, "--set", f"displacements={kinematics}",
                   "--set", "output.vtu=false", "--set", "output.plots=false"]
        for s in settings:
            command += ["--set", s]
        before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
        start = time.monotonic()
        try:
            run = subprocess.run(command, capture_output=True, text=True, timeout=60)
        except subprocess.TimeoutExpired:
            failed.append(f"{kinematics} {name}: no end within 60 s")
            continue
        seconds = time.monotonic() - start
        peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # the largest child so far
        line = f"{kinematics:5s} {name:10s} exit {run.returncode} in {seconds:5.2f} s"
        if peak_kb > max(before, 1024 * 1024):
            failed.append(f"{line}: a child took {peak_kb / 1024:.0f} MiB, over 1 GB")
        if run.returncode == 0:
            contact = json.load(open(os.path.join(out, "summary.json")))["contact"]
            force, load = contact["total_normal_force"], contact["applied_load"]
            balance = abs(force - load) / abs(load)
            print(f"{line}: solved, contact force {force:.6e} N for a load of {load:.6e} N ({balance:.1e})")
            if not (math.isfinite(force) and balance <= 1e-6):
                failed.append(f"{line}: contact force {force} against the load {load}")
        elif run.returncode == 1:
            lines = [l for l in run.stderr.splitlines() if l.startswith("feticon: error")]
            print(f"{line}: {lines[-1] if lines else run.stderr.strip()[-200:]}")
            if len(lines) != 1 or "\n" in lines[0]:
                failed.append(f"{line}: not one error line: {run.stderr[-400:]}")
        else:
            failed.append(f"{line}: {run.stderr[-400:]}")
if failed:
    sys.exit("magnitudes.sh:\n" + "\n".join(failed))
PY
