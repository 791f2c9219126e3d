#!/usr/bin/env python3
"""Runs every case (or those whose names start with PREFIX) at the ends of each parameter's
documented range, one parameter at a time, and prints each run that does not pass: the work list of
issue 14 class 5 ("rodvv list -v must not promise what a run refuses").

    scripts/range_scan.py [--rodvv PATH] [--timeout SECONDS] [PREFIX]

Per parameter it tries the upper end of the range (just inside an open end) and the lower end (just
inside; default/100 for an open zero end, 10 x the lower end of a range wider than 100x). A line per
run that exits non-zero: the exit code, the case, the assignment, the last line of the gate table and
the last line of stderr. Exit 2 naming the user's parameter and range is an honest refusal; exit 2
naming an internal name, exit 1 and a timeout are work to do. Takes about an hour for every case.
"""
import argparse
import re
import subprocess
import sys

RANGE = re.compile(r"\s+--set (\S+)=(\S+)\s+a finite number in ([\(\[])([^,]+), ([^\]\)]+)([\]\)])")


def parameters_of(rodvv):
    listing = subprocess.run([rodvv, "list", "-v"], capture_output=True, text=True, check=True).stdout
    cases, current = {}, None
    for line in listing.splitlines():
        if line and not line.startswith(" "):
            current = line.split()[0]
            cases[current] = []
        match = RANGE.match(line)
        if match and current:
            name, default, left, low, high, right = match.groups()
            cases[current].append((name, float(default), left, float(low), float(high), right))
    return cases


def range_ends(default, left, low, high, right):
    top = high if right == "]" else high - 1e-6 * abs(high)
    if low == 0.0 and left == "(":
        bottom = default / 100.0
    elif low > 0.0 and high / low > 100.0:
        bottom = low * 10.0 if left == "(" else low * 1.001
    else:
        bottom = low if left == "[" else low + 0.01 * (high - low)
    return [v for v in (bottom, top) if v != default]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("prefix", nargs="?", default="")
    parser.add_argument("--rodvv", default="build/release/apps/rodvv")
    parser.add_argument("--timeout", type=float, default=120.0)
    args = parser.parse_args()
    failures = 0
    for case, parameters in parameters_of(args.rodvv).items():
        if not case.startswith(args.prefix):
            continue
        for name, default, left, low, high, right in parameters:
            for value in range_ends(default, left, low, high, right):
                command = [args.rodvv, "run", case, "--set", f"{name}={value:.17g}"]
                try:
                    run = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
                except subprocess.TimeoutExpired:
                    print(f"timeout {case} {name}={value:.6g}", flush=True)
                    failures += 1
                    continue
                if run.returncode != 0:
                    failures += 1
                    table = (run.stdout.strip().splitlines() or [""])[-1]
                    error = (run.stderr.strip().splitlines() or [""])[-1]
                    print(f"rc={run.returncode} {case} {name}={value:.6g} :: {table[:90]} :: {error[:200]}", flush=True)
    print(f"{failures} runs did not pass", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
