#!/usr/bin/env python3
"""For each failing range end that scripts/range_scan.py printed, finds by bisection the end the case
honours: the value between the default (which passes) and the failing end where `rodvv run` stops
passing. Prints, per failing end, the last passing value, the first failing one and the failure there.

    scripts/range_scan.py > scan.txt
    scripts/range_bisect.py [--rodvv PATH] [--steps N] [--timeout SECONDS] scan.txt

Bisects in log space where both values are positive and a factor of 10 or more apart, in linear space
otherwise. A range narrowed to the result should be rounded inward and rescanned: the bisection assumes
a single pass/fail boundary between the default and the end, which the rescan checks at the new ends.
"""
import argparse
import math
import re
import subprocess
import sys

FAILING = re.compile(r"^(?:rc=\d+|timeout) (\S+) (\S+)=(\S+)")


def default_of(rodvv, case, name):
    listing = subprocess.run([rodvv, "list", "-v", case], capture_output=True, text=True, check=True).stdout
    match = re.search(rf"--set {re.escape(name)}=(\S+)", listing)
    return float(match.group(1))


def passes(rodvv, case, name, value, timeout):
    try:
        run = subprocess.run([rodvv, "run", case, "--set", f"{name}={value:.17g}"], capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return False, "timeout"
    if run.returncode == 0:
        return True, ""
    table = (run.stdout.strip().splitlines() or [""])[-1]
    error = (run.stderr.strip().splitlines() or [""])[-1]
    return False, f"rc={run.returncode} {table[:60]} {error[:160]}"


def midpoint(good, bad):
    if good > 0 and bad > 0 and max(good, bad) / min(good, bad) >= 10:
        return math.sqrt(good * bad)
    return 0.5 * (good + bad)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scan")
    parser.add_argument("--rodvv", default="build/release/apps/rodvv")
    parser.add_argument("--steps", type=int, default=7)
    parser.add_argument("--timeout", type=float, default=120.0)
    args = parser.parse_args()
    with open(args.scan, encoding="utf-8") as scan:
        ends = [match.groups() for match in map(FAILING.match, scan) if match]
    for case, name, end in ends:
        good, bad = default_of(args.rodvv, case, name), float(end)
        why = passes(args.rodvv, case, name, bad, args.timeout)[1]
        for _ in range(args.steps):
            value = midpoint(good, bad)
            ok, reason = passes(args.rodvv, case, name, value, args.timeout)
            if ok:
                good = value
            else:
                bad, why = value, reason
        print(f"{case} {name}: passes at {good:.4g}, fails at {bad:.4g} :: {why}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
