#!/usr/bin/env python3
"""Lists the functions that a gcovr JSON report (gcovr --json) records as never executed, by file.

    scripts/uncalled_functions.py coverage.json [PATH_PREFIX]

Only files whose path starts with PATH_PREFIX (default: all). Function names are gcovr's (demangled by gcov).
The last line counts them against all functions of those files.
"""
import json
import sys


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    report = json.load(open(sys.argv[1]))
    prefix = sys.argv[2] if len(sys.argv) > 2 else ""
    total = uncalled = 0
    for entry in sorted(report.get("files", []), key=lambda f: f["file"]):
        if not entry["file"].startswith(prefix):
            continue
        functions = entry.get("functions", [])
        total += len(functions)
        never = [f for f in functions if f.get("execution_count", 0) == 0]
        if never:
            print(entry["file"])
            for f in sorted(never, key=lambda f: f.get("lineno", 0)):
                print(f"    {f.get('lineno', '?')}: {f.get('name', '?')}")
        uncalled += len(never)
    print(f"{uncalled} of {total} functions never called")


if __name__ == "__main__":
    main()
