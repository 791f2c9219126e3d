#!/usr/bin/python3
"""Plots of a rodvv results.json (schema_version 1), for the HTML report.

    /usr/bin/python3 plot_results.py results.json OUTDIR/plots

Writes into OUTDIR/plots:
  <case>-convergence.png       log-log error vs h per error metric, least-squares fit, theory
  <case>-series-<name>.png     every series of the case's finest level; series named
                               "<plot>|<label>" share one figure <plot> with a legend (e.g.
                               "shape|computed" and "shape|closed form"); a series whose axes are
                               labelled "x" and "y" is drawn with equal aspect (a rod's shape)
  group-<group>-<name>.png     an unlabelled series overlaid across the cases of a group (finest levels)
  manifest.json                {"cases": {name: [{"file", "caption"}]}, "groups": {...}}
File names in the manifest are relative to OUTDIR (they start with "plots/").

Exit status: 0 on success, 2 on malformed input, 3 when matplotlib is missing. The last line
on stderr says why; rodvv shows it in index.html as "plots unavailable: ...".
Uses only matplotlib (Agg backend) and the standard library; no network.
"""

import concurrent.futures
import concurrent.futures.process
import json
import math
import multiprocessing
import os
import re
import sys

SCHEMA_VERSION = 1
DPI = 90
FIGSIZE = (6.0, 4.0)
# y spanning more than this many decades (all y != 0) is drawn as |y| on a log axis.
LOG_DECADES = 3.0
MAX_WORKERS = 4


class InputProblem(Exception):
    pass


def slugify(text):
    """The rule of rodvv::reports::slugify: every non-alphanumeric character becomes '-'."""
    return re.sub(r"[^A-Za-z0-9]", "-", text)


def finite(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def need(obj, key, kind, path):
    if not isinstance(obj, dict):
        raise InputProblem(f"field '{path}': expected an object")
    if key not in obj:
        raise InputProblem(f"field '{path}.{key}' is missing")
    value = obj[key]
    if kind is not None and not isinstance(value, kind):
        raise InputProblem(f"field '{path}.{key}': expected {kind_name(kind)}, "
                           f"got {type(value).__name__}")
    return value


def kind_name(kind):
    names = {list: "an array", dict: "an object", str: "a string"}
    return names.get(kind, getattr(kind, "__name__", str(kind)))


def load(path):
    try:
        with open(path, encoding="utf-8") as stream:
            document = json.load(stream)
    except OSError as error:
        raise InputProblem(f"cannot open: {error.strerror}") from error
    except json.JSONDecodeError as error:
        raise InputProblem(f"not valid JSON: {error}") from error
    if not isinstance(document, dict):
        raise InputProblem("expected a JSON object at the top level")
    version = document.get("schema_version")
    if version != SCHEMA_VERSION:
        raise InputProblem(f"field 'schema_version': unsupported version {version!r}, "
                           f"this script reads {SCHEMA_VERSION}")
    cases = need(document, "cases", list, "")
    for i, case in enumerate(cases):
        path = f"cases[{i}]"
        info = need(case, "info", dict, path)
        need(info, "name", str, path + ".info")
        for j, level in enumerate(need(case, "levels", list, path)):
            lpath = f"{path}.levels[{j}]"
            need(level, "metrics", dict, lpath)
            for k, series in enumerate(need(level, "series", list, lpath)):
                spath = f"{lpath}.series[{k}]"
                need(series, "name", str, spath)
                xs, ys = need(series, "x", list, spath), need(series, "y", list, spath)
                if len(xs) != len(ys):
                    raise InputProblem(f"field '{spath}.y': {len(ys)} values but x has {len(xs)}")
        need(case, "analyses", list, path)
    return cases


class UniqueNames:
    """Distinct names may share a slug: the second gets "-2", and so on."""

    def __init__(self):
        self.used = set()

    def __call__(self, stem):
        name, n = stem, 2
        while name in self.used:
            name = f"{stem}-{n}"
            n += 1
        self.used.add(name)
        return name


class PlotWriter:
    def __init__(self, plt, ticker, outdir):
        self.plt = plt
        self.ticker = ticker
        self.outdir = outdir
        # Paths in the manifest are relative to the report directory, the parent of outdir.
        self.prefix = os.path.basename(os.path.normpath(outdir))

    def save(self, fig, name):
        fig.savefig(os.path.join(self.outdir, name + ".png"), dpi=DPI)
        self.plt.close(fig)
        return f"{self.prefix}/{name}.png"

    def log_axis(self, axis):
        # Plain "1e-05" labels: the default mathtext labels cost a third of the run time.
        axis.set_major_formatter(self.ticker.LogFormatter())
        axis.set_minor_formatter(self.ticker.LogFormatter(labelOnlyBase=False))

    def figure(self, title, xlabel, ylabel):
        # Fixed margins: constrained/tight layout would double the drawing time per figure.
        fig, ax = self.plt.subplots(figsize=FIGSIZE)
        fig.subplots_adjust(left=0.15, right=0.97, bottom=0.13, top=0.88)
        ax.set_title(title, fontsize=9)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
        return fig, ax


def error_metrics(case):
    # Errors and invariants both converge (an invariant's error is its deviation from the exact
    # value, e.g. |E - E(0)|); diagnostics have no error to plot.
    return [m for m in case["info"].get("metrics", []) if m.get("kind") in ("error", "invariant")]


def convergence_plot(writer, case, stem):
    info = case["info"]
    levels = case["levels"]
    analyses = {a.get("metric"): a for a in case.get("analyses", []) if isinstance(a, dict)}
    curves = []
    for spec in error_metrics(case):
        points = []
        for level in levels:
            sample = level["metrics"].get(spec["name"])
            h = level.get("h")
            if isinstance(sample, dict) and finite(sample.get("error")) and sample["error"] > 0 \
                    and finite(h) and h > 0:
                points.append((h, sample["error"]))
        if len(points) >= 2:
            curves.append((spec, points))
    if not curves:
        return None
    resolution = info.get("resolution", {}).get("name", "")
    fig, ax = writer.figure(info["name"], "h" + (f"  ({resolution})" if resolution else ""), "error")
    ax.set_xscale("log")
    ax.set_yscale("log")
    writer.log_axis(ax.xaxis)
    writer.log_axis(ax.yaxis)
    # One legend entry per metric carrying both slopes, plus one entry per line style, keeps the
    # legend small with several metrics.
    any_fit = any_theory = False
    for index, (spec, points) in enumerate(curves):
        color = f"C{index % 10}"
        hs = [p[0] for p in points]
        es = [p[1] for p in points]
        order = analyses.get(spec["name"], {}).get("order", {})
        slope = order.get("least_squares")
        used = order.get("levels_used") or 0
        theory = spec.get("theoretical_order")
        label = spec["name"]
        slopes = []
        if finite(slope):
            slopes.append(f"fit slope {slope:.2f}")
        if finite(theory):
            slopes.append(f"theory {theory:g}")
        if slopes:
            label += " (" + ", ".join(slopes) + ")"
        ax.plot(hs, es, "o-", color=color, label=label)
        if finite(slope) and isinstance(used, int) and used >= 2:
            any_fit = True
            # The fit covers the last `used` levels (the finest); its intercept is the mean
            # offset of those points from the fitted slope.
            tail = points[-min(used, len(points)):]
            offset = sum(math.log(e) - slope * math.log(h) for h, e in tail) / len(tail)
            xs = [tail[0][0], tail[-1][0]]
            ax.plot(xs, [math.exp(offset) * x ** slope for x in xs], "-", color=color,
                    linewidth=4, alpha=0.3)
        if finite(theory):
            any_theory = True
            h_fine, e_fine = min(points, key=lambda p: p[0])
            xs = [min(hs), max(hs)]
            ax.plot(xs, [e_fine * (x / h_fine) ** theory for x in xs], "--", color=color,
                    linewidth=1)
    if any_fit:
        ax.plot([], [], "-", color="gray", linewidth=4, alpha=0.3,
                label="least-squares fit (finest levels used)")
    if any_theory:
        ax.plot([], [], "--", color="gray", linewidth=1, label="theoretical slope at finest h")
    # Errors fall towards small h, so the upper left is usually free (and "best" is slow).
    ax.legend(fontsize=7, loc="upper left", framealpha=0.85)
    file = writer.save(fig, stem)
    return {"file": file, "caption": f"{info['name']}: error vs h (log-log) with the least-squares "
                                     f"fit and the theoretical slope"}


def finest_level(case):
    """The level with series and the smallest h (levels are listed coarse to fine)."""
    best = None
    for level in case["levels"]:
        if not level.get("series"):
            continue
        h = level.get("h")
        if best is None or (finite(h) and (not finite(best.get("h")) or h <= best["h"])):
            best = level
    return best


def clean_xy(series):
    xs, ys = [], []
    for x, y in zip(series["x"], series["y"]):
        if finite(x) and finite(y):
            xs.append(x)
            ys.append(y)
    return xs, ys


def wants_log(all_y):
    if not all_y or any(y == 0 for y in all_y):
        return False
    magnitudes = [abs(y) for y in all_y]
    return math.log10(max(magnitudes) / min(magnitudes)) > LOG_DECADES


def plot_key(series_name):
    """"shape|computed" -> ("shape", "computed"); a plain name is its own plot, unlabelled."""
    key, _, label = series_name.partition("|")
    return key, label


def series_plot(writer, case, level, members, stem):
    """One figure for the series sharing a plot key (members: list of series dicts)."""
    curves = [(plot_key(series["name"])[1], *clean_xy(series)) for series in members]
    curves = [c for c in curves if c[1]]
    if not curves:
        return None
    first = members[0]
    key = plot_key(first["name"])[0]
    name = case["info"]["name"]
    log = wants_log([y for _, _, ys in curves for y in ys])
    ylabel = first.get("y_label") or key
    xlabel = first.get("x_label") or "x"
    fig, ax = writer.figure(f"{name}\n{key}", xlabel, f"|{ylabel}|" if log else ylabel)
    if log:
        ax.set_yscale("log")
        writer.log_axis(ax.yaxis)
    if xlabel == "x" and ylabel == "y":
        ax.set_aspect("equal", adjustable="datalim")
    styles = ["-", "--", ":", "-."]
    for i, (label, xs, ys) in enumerate(curves):
        ax.plot(xs, [abs(y) for y in ys] if log else ys, styles[i % len(styles)], linewidth=1.2,
                label=label or None)
    if any(label for label, _, _ in curves):
        ax.legend(fontsize=7)
    file = writer.save(fig, stem)
    h = level.get("h")
    at = f"h = {h:.4g}" if finite(h) else "finest level"
    return {"file": file, "caption": f"{key} ({at})" + (", |y| on a log axis" if log else "")}


def legend_label(info):
    label = info.get("method") or info.get("title") or info["name"]
    return label if len(label) <= 60 else label[:57] + "..."


def group_plot(writer, group, series_name, members, stem):
    all_y = []
    for _, series in members:
        all_y.extend(clean_xy(series)[1])
    if not all_y:
        return None
    log = wants_log(all_y)
    first = members[0][1]
    ylabel = first.get("y_label") or series_name
    fig, ax = writer.figure(f"{group}: {series_name}", first.get("x_label") or "x",
                            f"|{ylabel}|" if log else ylabel)
    if log:
        ax.set_yscale("log")
        writer.log_axis(ax.yaxis)
    for info, series in members:
        xs, ys = clean_xy(series)
        ax.plot(xs, [abs(y) for y in ys] if log else ys, "-", linewidth=1.2,
                label=legend_label(info))
    ax.legend(fontsize=7, loc="upper left", framealpha=0.85)
    file = writer.save(fig, stem)
    names = ", ".join(info["name"] for info, _ in members)
    return {"file": file, "caption": f"{series_name} across group {group} (finest level of each "
                                     f"case: {names})"}


def plan(cases):
    """The plot jobs in manifest order: one per case, then one per group overlay. File stems are
    made unique here, so parallel workers never write the same file."""
    unique = UniqueNames()
    case_jobs, overlays = [], {}  # overlays: group -> series name -> [case index]
    for index, case in enumerate(cases):
        info = case["info"]
        stem = unique(slugify(info["name"]))
        series_stems, names = [], UniqueNames()
        level = finest_level(case)
        seen, by_key = set(), {}
        for k, series in enumerate(level["series"] if level else []):
            if series["name"] in seen:
                continue
            seen.add(series["name"])
            key = plot_key(series["name"])[0]
            if key not in by_key:
                by_key[key] = []
                series_stems.append((by_key[key], names(f"{stem}-series-{slugify(key)}")))
            by_key[key].append(k)
            group = info.get("group")
            # Labelled series ("plot|label") are already compared inside their case's figure.
            if isinstance(group, str) and group and not plot_key(series["name"])[1]:
                overlays.setdefault(group, {}).setdefault(series["name"], []).append(index)
        case_jobs.append(("case", index, stem + "-convergence", series_stems))
    group_jobs = []
    for group, by_series in overlays.items():
        for series_name, members in by_series.items():
            if len(members) > 1:
                stem = unique(f"group-{slugify(group)}-{slugify(series_name)}")
                group_jobs.append(("group", group, series_name, members, stem))
    return case_jobs + group_jobs


_STATE = {}  # cases and writer, set before the worker processes are forked


def run_job(job):
    cases, writer = _STATE["cases"], _STATE["writer"]
    if job[0] == "case":
        _, index, convergence_stem, series_stems = job
        case = cases[index]
        entries = [convergence_plot(writer, case, convergence_stem)]
        level = finest_level(case)
        for indices, stem in series_stems:
            entries.append(series_plot(writer, case, level, [level["series"][k] for k in indices],
                                       stem))
        return [e for e in entries if e]
    _, group, series_name, members, stem = job
    pairs = []
    for index in members:
        case = cases[index]
        level = finest_level(case)
        series = next(s for s in level["series"] if s["name"] == series_name)
        pairs.append((case["info"], series))
    entry = group_plot(writer, group, series_name, pairs, stem)
    return [entry] if entry else []


def run_jobs(jobs):
    """In parallel over the CPUs this process may use (fork keeps the loaded results shared);
    serially for a handful of jobs or where processes cannot be forked."""
    try:
        workers = min(len(os.sched_getaffinity(0)), MAX_WORKERS)
    except AttributeError:
        workers = 1
    if workers > 1 and len(jobs) >= 8:
        try:
            context = multiprocessing.get_context("fork")
            with concurrent.futures.ProcessPoolExecutor(workers, mp_context=context) as pool:
                return list(pool.map(run_job, jobs, chunksize=2))
        except (OSError, concurrent.futures.process.BrokenProcessPool):
            pass
    return [run_job(job) for job in jobs]


def main(argv):
    if len(argv) != 3:
        print("usage: plot_results.py results.json OUTDIR/plots", file=sys.stderr)
        return 2
    results_path, outdir = argv[1], argv[2]
    try:
        cases = load(results_path)
    except InputProblem as problem:
        print(f"plot_results.py: {results_path}: {problem}", file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker as ticker
    except ImportError as error:
        print(f"matplotlib is not available for {sys.executable} ({error})", file=sys.stderr)
        return 3
    os.makedirs(outdir, exist_ok=True)
    _STATE["cases"] = cases
    _STATE["writer"] = PlotWriter(plt, ticker, outdir)

    manifest = {"cases": {}, "groups": {}}
    try:
        jobs = plan(cases)
        for job, entries in zip(jobs, run_jobs(jobs)):
            if job[0] == "case":
                manifest["cases"][cases[job[1]]["info"]["name"]] = entries
            elif entries:
                manifest["groups"].setdefault(job[1], []).extend(entries)
    except (KeyError, TypeError, ValueError, StopIteration) as error:
        print(f"plot_results.py: {results_path}: malformed results ({type(error).__name__}: "
              f"{error})", file=sys.stderr)
        return 2
    with open(os.path.join(outdir, "manifest.json"), "w", encoding="utf-8") as stream:
        json.dump(manifest, stream, indent=2)
        stream.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
