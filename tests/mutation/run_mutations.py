#!/usr/bin/env python3
"""Measures what rodvv's checks catch (issue 13): applies each seeded defect of the catalogue alone to a
scratch copy of the tree, rebuilds incrementally, and asks whether it turns red

  1. `rodvv run` (every case at its default levels, the CI gate; two shards at once),
  2. the other tests (`ctest -LE rodvv`: unit, reference, CLI, fuzz-replay tests; the per-case CTest
     tests repeat `rodvv run` and are left out),
  3. only when both missed it: `rodvv run --extended` (the rest of the CI).

    tests/mutation/run_mutations.py [--only ID ...] [--family F] [--redo] [--jobs N]

Results go to tests/mutation/results.tsv (one row per defect, kept between runs: a defect already
there is skipped unless --redo) and the detection table to tests/mutation/results.md. A defect that
does not compile is recorded as such and counted apart (neither caught nor missed). The scratch copy
(--work, default /tmp/rodvv-mutation) holds the tracked files of the working tree; files that did not
change keep their times, so each rebuild recompiles only what a defect touches.
"""
import argparse
import csv
import filecmp
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
FIELDS = ["id", "family", "file", "compiles", "run_exit", "run_failed_cases", "tests_failed", "extended_exit",
          "caught_by", "seconds"]


def sh(command, cwd, timeout=None, env=None):
    """Runs a command, returns (exit code, stdout + stderr); a timeout is exit code 124."""
    try:
        done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)
        return done.returncode, done.stdout + done.stderr
    except subprocess.TimeoutExpired as expired:
        out = (expired.stdout or b"").decode(errors="replace") if isinstance(expired.stdout, bytes) else (expired.stdout or "")
        return 124, out + f"\n(timed out after {timeout} s)"


def sync_tree(work):
    """Copies the tracked files of the working tree into work/src, leaving unchanged files untouched."""
    src = work / "src"
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=REPO, capture_output=True, check=True).stdout
    for name in filter(None, listed.decode().split("\0")):
        origin, copy = REPO / name, src / name
        if not origin.is_file():
            continue  # deleted in the working tree
        if copy.is_file() and filecmp.cmp(origin, copy, shallow=False):
            continue
        copy.parent.mkdir(parents=True, exist_ok=True)
        # A fresh time stamp, not the origin's (copy2): an object built since the origin was last
        # edited (from a defect's copy) would otherwise look newer than the changed source, and the
        # incremental build would keep it.
        shutil.copy(origin, copy)
        os.utime(copy)
    return src


def build(src, jobs):
    build_dir = src / "build" / "mutation"
    if not (build_dir / "build.ninja").exists():
        code, out = sh(["cmake", "-S", ".", "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                        "-DRODVV_BUILD_BENCHMARKS=OFF"], cwd=src)
        if code != 0:
            sys.exit("configure failed:\n" + out[-3000:])
    code, out = sh(["cmake", "--build", str(build_dir), "-j", str(jobs)], cwd=src)
    return code == 0, out, build_dir


FAILED_CASE = re.compile(r"^\[\s*\d+/\d+\]\s+(\S+)\s+FAIL\b")


def failed_cases(text):
    """The cases of `rodvv run`'s progress lines "[i/n] case  FAIL (...)"."""
    return sorted({m.group(1) for m in map(FAILED_CASE.match, text.splitlines()) if m})


def run_gate(build_dir, extended=False):
    """`rodvv run` in two shards at once: the worst exit code and the failed cases."""
    rodvv = str(build_dir / "apps" / "rodvv")
    # A level budget of 120 s (the slowest default level takes about 25 s): a defect that makes a solver
    # crawl fails its level instead of costing the budget's default 300 s per level.
    args = [rodvv, "run", "--level-budget", "120"] + (["--extended"] if extended else [])
    shards = [subprocess.Popen(args + ["--shard", f"{i}/2"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
              for i in (1, 2)]
    code, failed = 0, []
    for shard in shards:
        try:
            out, _ = shard.communicate(timeout=3600)
        except subprocess.TimeoutExpired:
            shard.kill()
            out, _ = shard.communicate()
            shard.returncode = 124
        code = max(code, shard.returncode)
        failed += failed_cases(out)
    return code, failed


def other_tests(build_dir, jobs):
    code, out = sh(["ctest", "-LE", "rodvv", "-j", str(jobs), "--timeout", "300"], cwd=build_dir)
    failed = [line.split("-", 1)[1].split("(")[0].strip() for line in out.splitlines()
              if line.strip()[:1].isdigit() and " - " in line and ("Failed" in line or "Timeout" in line
                                                                 or "Exception" in line or "SEGFAULT" in line)]
    return code, failed


def load_results(path):
    if not path.exists():
        return {}
    with path.open() as f:
        return {row["id"]: row for row in csv.DictReader(f, delimiter="\t")}


def save_results(path, results):
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, FIELDS, delimiter="\t")
        writer.writeheader()
        for row in results.values():
            writer.writerow(row)


def table(results, catalogue):
    order = {entry["id"]: i for i, entry in enumerate(catalogue)}
    rows = sorted(results.values(), key=lambda r: order.get(r["id"], 1 << 30))
    compiled = [r for r in rows if r["compiles"] == "yes"]
    by_run = sum(r["run_exit"] not in ("0", "") for r in compiled)
    by_ci = sum(r["caught_by"] != "missed" for r in compiled)
    lines = ["# Mutation results (tests/mutation/run_mutations.py)", "",
             f"{len(rows)} defects run, {len(compiled)} compiled. Caught by `rodvv run` alone: {by_run} of "
             f"{len(compiled)} ({100.0 * by_run / max(1, len(compiled)):.0f} %); by the whole CI (`rodvv run`, "
             f"the other tests, `rodvv run --extended`): {by_ci} of {len(compiled)} "
             f"({100.0 * by_ci / max(1, len(compiled)):.0f} %).", "",
             "| defect | family | caught by | rodvv run: failed cases | other tests failed |", "|---|---|---|---|---|"]
    for r in rows:
        caught = r["caught_by"] if r["compiles"] == "yes" else "does not compile"
        lines.append(f"| {r['id']} | {r['family']} | {caught} | {r['run_failed_cases'][:120]} | "
                     f"{r['tests_failed'][:120]} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--catalogue", type=Path, default=HERE / "catalogue.json")
    parser.add_argument("--results", type=Path, default=HERE / "results.tsv")
    parser.add_argument("--work", type=Path, default=Path("/tmp/rodvv-mutation"))
    parser.add_argument("--only", nargs="*", default=None, help="defect ids")
    parser.add_argument("--family", default=None)
    parser.add_argument("--redo", action="store_true", help="run defects already in the results again")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()

    catalogue = json.loads(args.catalogue.read_text())
    ids = [entry["id"] for entry in catalogue]
    if len(set(ids)) != len(ids):
        sys.exit("catalogue: duplicate ids")
    selected = [e for e in catalogue if (args.only is None or e["id"] in args.only)
                and (args.family is None or e["family"] == args.family)]
    results = load_results(args.results)
    if not args.redo:
        selected = [e for e in selected if e["id"] not in results]
    if not selected:
        args.results.with_suffix(".md").write_text(table(results, catalogue))
        print(table(results, catalogue))
        return 0

    args.work.mkdir(parents=True, exist_ok=True)
    src = sync_tree(args.work)
    for entry in selected:  # every defect must apply to the tree as it is, before anything is built
        text = (src / entry["file"]).read_text()
        if text.count(entry["find"]) != 1:
            sys.exit(f"{entry['id']}: its text occurs {text.count(entry['find'])} times in {entry['file']}, not once")
    ok, out, build_dir = build(src, args.jobs)
    if not ok:
        sys.exit("the unmutated tree does not build:\n" + out[-3000:])
    code, failed = run_gate(build_dir)
    if code != 0:
        sys.exit(f"the unmutated tree fails `rodvv run` (exit {code}): {failed}")
    print(f"baseline: builds, `rodvv run` passes; {len(selected)} defects to run", flush=True)

    for entry in selected:
        start = time.monotonic()
        path = src / entry["file"]
        original = path.read_text()
        row = {"id": entry["id"], "family": entry["family"], "file": entry["file"], "compiles": "no", "run_exit": "",
               "run_failed_cases": "", "tests_failed": "", "extended_exit": "", "caught_by": "", "seconds": ""}
        try:
            path.write_text(original.replace(entry["find"], entry["replace"], 1))
            ok, _, build_dir = build(src, args.jobs)
            if ok:
                row["compiles"] = "yes"
                run_code, run_failed = run_gate(build_dir)
                test_code, test_failed = other_tests(build_dir, args.jobs)
                row.update(run_exit=str(run_code), run_failed_cases=" ".join(run_failed),
                           tests_failed=" ".join(test_failed) or ("" if test_code == 0 else f"exit {test_code}"))
                caught = (["rodvv run"] if run_code != 0 else []) + (["tests"] if test_code != 0 else [])
                if not caught:
                    extended_code, extended_failed = run_gate(build_dir, extended=True)
                    row["extended_exit"] = str(extended_code)
                    if extended_code != 0:
                        caught = ["rodvv run --extended"]
                        row["run_failed_cases"] = " ".join(extended_failed)
                row["caught_by"] = " + ".join(caught) or "missed"
        finally:
            path.write_text(original)
        row["seconds"] = f"{time.monotonic() - start:.0f}"
        results[entry["id"]] = row
        save_results(args.results, results)
        print(f"{entry['id']}: {row['caught_by'] or 'does not compile'} ({row['seconds']} s)", flush=True)
    build(src, args.jobs)  # leave the scratch build unmutated
    (args.results.with_suffix(".md")).write_text(table(results, catalogue))
    print(table(results, catalogue))
    return 0


if __name__ == "__main__":
    sys.exit(main())
