#!/usr/bin/env python3
"""Regression gates end to end (issue 13, class 6): `rodvv run` against a copy of the tree's goldens
passes; the same copy with one error moved by 10 % - the size of change a verification bound of twice
the measured constant lets through - fails the case (exit 1, the regression gate named); `rodvv bless`
on the copy prints what moved and restores it; a malformed goldens file is bad input (exit 2, the
field named), whatever is wrong in it.

usage: golden_regression.py <rodvv> <tree goldens> <work dir>
"""
import json
import os
import shutil
import subprocess
import sys

CASE = "pendulum/libration-30/stormer-verlet"


def run(*args):
    proc = subprocess.run(list(args), capture_output=True, text=True)
    return proc.returncode, proc.stdout + proc.stderr


def main(argv):
    rodvv, tree, work = argv[1], argv[2], argv[3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    copy = os.path.join(work, "goldens.json")
    shutil.copy(tree, copy)
    failures = []

    code, out = run(rodvv, "run", CASE, "--goldens", copy)
    if code != 0 or "regression: metrics match their goldens" not in out:
        failures.append(f"unchanged goldens: expected exit 0 with the regression gate, got {code}:\n{out}")

    with open(copy) as f:
        doc = json.load(f)
    level = doc["cases"][CASE][-1]
    metric = next(name for name, sample in level["metrics"].items() if "error" in sample)
    level["metrics"][metric]["error"] *= 1.1
    with open(copy, "w") as f:
        json.dump(doc, f, indent=1)
    code, out = run(rodvv, "run", CASE, "--goldens", copy)
    failing = [line for line in out.splitlines() if "regression:" in line and "FAIL" in line]
    if code != 1 or not failing:
        failures.append(f"error moved by 10 %: expected exit 1 and a failed regression gate, got {code}:\n{out}")

    code, out = run(rodvv, "bless", CASE, "--goldens", copy)
    if code != 0 or "changed" not in out or metric not in out:
        failures.append(f"bless: expected exit 0 naming the changed {metric}, got {code}:\n{out}")
    code, out = run(rodvv, "run", CASE, "--goldens", copy)
    if code != 0:
        failures.append(f"after bless: expected exit 0, got {code}:\n{out}")
    with open(copy) as f, open(tree) as g:
        if json.load(f)["cases"][CASE] != json.load(g)["cases"][CASE]:
            failures.append("bless did not restore the tree's goldens of the case")

    # Malformed files, each wrong in one field's type or value: exit 2 naming it (never exit 3).
    for text, field in [
        ('{"format": "rodvv goldens", "version": 1, "cases": {"x": [{"level": "abc", "metrics": {}}]}}', "cases.x[0].level"),
        ('{"format": 5}', "top level"),
        ('[1, 2]', "top level"),
        ('{"format": "rodvv goldens", "version": "1", "cases": {}}', "version"),
        ('{"format": "rodvv goldens", "version": 1, "cases": {"x": [{"level": 1, "failed": 3, "metrics": {}}]}}',
         "cases.x[0].failed"),
    ]:
        with open(copy, "w") as f:
            f.write(text)
        code, out = run(rodvv, "run", CASE, "--goldens", copy)
        if code != 2 or field not in out:
            failures.append(f"malformed goldens {text}: expected exit 2 naming {field}, got {code}:\n{out}")

    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
