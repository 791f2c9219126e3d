#!/usr/bin/python3
"""Plots of a rodvv results.json (schema_version 1), for the HTML report.

    /usr/bin/python3 plot_results.py results.json OUTDIR/plots [--progress-fd=N]

--progress-fd: an open descriptor (rodvv passes its own stderr) for a progress bar of the figures.

Writes into OUTDIR/plots:
  <case>-convergence.png       log-log error vs h per error metric, least-squares fit, theory
  <case>-series-<name>.png     every series of the case's finest level; series named
                               "<plot>|<label>" share one figure <plot> with a legend (e.g.
                               "shape|computed" and "shape|closed form"); a series whose axes are
                               labelled "x" and "y" is drawn with equal aspect (a rod's shape);
                               a label starting "levels: " marks a measurement each level adds
                               to a curve (a law over a parameter the levels vary): its points
                               are gathered from every level and drawn as markers
  group-<group>-<name>.png     an unlabelled series overlaid across the cases of a group (finest levels)
  group-<group>-<metric>-vs-h.png
                               for a group of two or more cases, per error metric (kind "error")
                               that at least two of them can draw: error vs h, one line per case,
                               with a theoretical-order slope triangle
  group-<group>-<metric>-work-precision.png
                               the same errors against the time each level took (its CPU time
                               where results.json records "cpu_seconds", else "wall_seconds")
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
    """The validated document (its "cases" checked as far as the plots need)."""
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
    return document


def timing_note(document):
    """Where the per-level times of a work-precision figure were measured, for its caption."""
    provenance = document.get("provenance")
    provenance = provenance if isinstance(provenance, dict) else {}
    merged = document.get("merged_from")
    if isinstance(merged, list) and merged:
        return "on the machines of the merged runs (cases run on different machines are not comparable)"
    machine = []
    if isinstance(provenance.get("cpu_model"), str) and provenance["cpu_model"]:
        machine.append(provenance["cpu_model"])
    cores = provenance.get("host_cores")
    if finite(cores) and cores > 0:
        machine.append(f"{cores:g} cores")
    build = provenance.get("build_type")
    if isinstance(build, str) and build:
        machine.append(f"{build} build")
    return "on the machine that ran the report" + (f" ({', '.join(machine)})" if machine else "")


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
        # Minor ticks at 2 and 5 of each decade, not at 2 .. 9: every tick is a Python object with two
        # marker lines, a grid line and two labels, and the eight per decade were a quarter of the CPU
        # time of the plots (measured: 25.6 -> 19.0 s for the first 330 figures of the report).
        axis.set_minor_locator(self.ticker.LogLocator(base=10.0, subs=(2.0, 5.0), numticks=12))

    def figure(self, title, xlabel, ylabel):
        # Fixed margins: constrained/tight layout would double the drawing time per figure.
        fig, ax = self.plt.subplots(figsize=FIGSIZE)
        fig.subplots_adjust(left=0.15, right=0.97, bottom=0.13, top=0.88)
        # An explicit y: matplotlib then skips placing the title clear of the top axis's tick labels
        # (a tight bounding box of the whole axis per draw: a third of the drawing time), which
        # these plots, with no top axis, do not need.
        ax.set_title(title, fontsize=9, y=1.01)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
        return fig, ax


def error_metrics(case):
    # Errors and invariants both converge (an invariant's error is its deviation from the exact
    # value, e.g. |E - E(0)|); diagnostics have no error to plot.
    return [m for m in case["info"].get("metrics", []) if m.get("kind") in ("error", "invariant")]


def parameter_study_plot(writer, case, stem):
    """A case whose levels are a physical parameter, not a mesh (resolution scale "parameter"): each
    error over the level itself, no slopes (an order in a parameter means nothing)."""
    info = case["info"]
    resolution = info.get("resolution", {})
    curves = []
    for spec in error_metrics(case):
        points = [(level["level"], level["metrics"][spec["name"]]["error"]) for level in case["levels"]
                  if finite(level.get("level")) and isinstance(level["metrics"].get(spec["name"]), dict)
                  and finite(level["metrics"][spec["name"]].get("error"))
                  and level["metrics"][spec["name"]]["error"] > 0]
        if points:
            curves.append((spec, points))
    if not curves:
        return None
    name = resolution.get("name", "level")
    fig, ax = writer.figure(info["name"], f"{name} (a parameter study, not a mesh)", "error")
    ax.set_yscale("log")
    writer.log_axis(ax.yaxis)
    for index, (spec, points) in enumerate(curves):
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=f"C{index % 10}", label=spec["name"])
    ax.legend(fontsize=7, loc="best", framealpha=0.85)
    file = writer.save(fig, stem)
    return {"file": file, "caption": f"{info['name']}: each error over {name} (the levels are a parameter "
                                     f"study: no order is fitted)"}


def convergence_plot(writer, case, stem):
    info = case["info"]
    if info.get("resolution", {}).get("scale") == "parameter":
        return parameter_study_plot(writer, case, stem)
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


LEVELS_PREFIX = "levels: "


def gathered_over_levels(case, series):
    """A "levels: " series with the points of every level that has it (level order); others as they are."""
    if not plot_key(series["name"])[1].startswith(LEVELS_PREFIX):
        return series
    xs, ys = [], []
    for level in case["levels"]:
        for other in level.get("series") or []:
            if other["name"] == series["name"]:
                xs.extend(other["x"])
                ys.extend(other["y"])
    return dict(series, x=xs, y=ys)


def series_plot(writer, case, level, members, stem):
    """One figure for the series sharing a plot key (members: list of series dicts)."""
    members = [gathered_over_levels(case, series) for series in members]
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
    lines = 0
    for label, xs, ys in curves:
        ys = [abs(y) for y in ys] if log else ys
        if label.startswith(LEVELS_PREFIX):
            ax.plot(xs, ys, "o", markersize=5, label=label[len(LEVELS_PREFIX):] + " (one point per level)")
        else:
            ax.plot(xs, ys, styles[lines % len(styles)], linewidth=1.2, label=label or None)
            lines += 1
    if any(label for label, _, _ in curves):
        ax.legend(fontsize=7)
    file = writer.save(fig, stem)
    h = level.get("h")
    at = f"h = {h:.4g}" if finite(h) else "finest level"
    if any(label.startswith(LEVELS_PREFIX) for label, _, _ in curves):
        at += "; the markers: every level"
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


def member_label(info, group, limit=80):
    """The case's name within its group and its method: methods alone can coincide (two contact
    algorithms on one discretisation)."""
    name = info["name"]
    if name.startswith(group + "/"):
        name = name[len(group) + 1:]
    method = info.get("method") or info.get("title") or ""
    label = f"{name}: {method}" if method else name
    return label if len(label) <= limit else label[:limit - 3] + "..."


def error_spec(case, metric):
    """The case's spec of `metric` if it is an error metric (kind "error"), else None."""
    for spec in case["info"].get("metrics", []):
        if isinstance(spec, dict) and spec.get("name") == metric and spec.get("kind") == "error":
            return spec
    return None


def error_levels(case, metric):
    """(level, error) for the levels with a finite positive error of `metric`, coarse to fine."""
    out = []
    for level in case["levels"]:
        sample = level["metrics"].get(metric)
        if isinstance(sample, dict) and finite(sample.get("error")) and sample["error"] > 0:
            out.append((level, sample["error"]))
    return out


def h_points(case, metric):
    return [(level["h"], e) for level, e in error_levels(case, metric)
            if finite(level.get("h")) and level["h"] > 0]


def level_seconds(level, clock):
    seconds = level.get("cpu_seconds" if clock == "cpu" else "wall_seconds")
    return seconds if finite(seconds) and seconds > 0 else None


def time_points(case, metric, clock):
    """(seconds, error, level value) per level with an error and a positive time."""
    out = []
    for level, e in error_levels(case, metric):
        seconds = level_seconds(level, clock)
        if seconds is not None:
            out.append((seconds, e, level.get("level")))
    return out


def shared_error_metrics(cases, members):
    """[(metric, [case index])] for the error metrics with a theoretical order (convergence
    quantities: round-off metrics would only add noise and plotting time) that at least two of the
    members can draw (finite positive errors at two or more levels), in the order the members list
    them."""
    order, who = [], {}
    for index in members:
        case = cases[index]
        for spec in case["info"].get("metrics", []):
            if not isinstance(spec, dict) or spec.get("kind") != "error" \
                    or not isinstance(spec.get("name"), str) or spec.get("theoretical_order") is None:
                continue
            name = spec["name"]
            if len(error_levels(case, name)) < 2:
                continue
            if name not in who:
                who[name] = []
                order.append(name)
            if index not in who[name]:
                who[name].append(index)
    return [(name, who[name]) for name in order if len(who[name]) >= 2]


def common_text(values):
    """The one string all values share, else ""."""
    values = set(v if isinstance(v, str) else "" for v in values)
    return values.pop() if len(values) == 1 else ""


def legend_below(fig, ax):
    """The legend under the axes, the figure taller by its height: with several cases or long
    method names no corner of the axes is reliably free of data."""
    handles, labels = ax.get_legend_handles_labels()
    width, height = FIGSIZE
    extra = 0.06 + 0.16 * len(labels)
    total = height + extra
    fig.set_size_inches(width, total)
    # The axes keep the size and margins writer.figure gives them in a FIGSIZE figure.
    fig.subplots_adjust(bottom=(0.13 * height + extra) / total, top=1.0 - 0.12 * height / total)
    fig.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 0.0), fontsize=7,
               frameon=False)


def thin_log_ticks(writer, ax):
    """No minor ticks on a log axis spanning more than two decades, where the decades carry the
    labels: making the ticks is most of the drawing time (these figures come by the hundred)."""
    for axis, (low, high) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        if low > 0 and high > 0 and abs(math.log10(high / low)) > 2.0:
            axis.set_minor_locator(writer.ticker.NullLocator())


def slope_triangle(ax, points, order, color):
    """A right triangle of slope `order` under the finest point of `points` ((h, error), any
    order), its horizontal leg one refinement step long, labelled with the order."""
    points = sorted(points)
    (h0, e0), h1 = points[0], points[1][0]
    ratio = min(max(h1 / h0, 1.5), 4.0)
    x0, x1 = h0, h0 * ratio
    y0 = e0 / 3.0
    y1 = y0 * ratio ** order
    ax.plot([x0, x1, x1, x0], [y0, y0, y1, y0], "-", color=color, linewidth=0.9)
    ax.annotate(f"{order:g}", (x1, math.sqrt(y0 * y1)), xytext=(3, 0), textcoords="offset points",
                fontsize=7, color=color, va="center")
    ax.annotate("1", (math.sqrt(x0 * x1), y0), xytext=(0, -3), textcoords="offset points",
                fontsize=7, color=color, ha="center", va="top")


def group_error_plot(writer, group, metric, members, stem):
    """Error of `metric` vs h for the member cases, one line each."""
    curves = [(case["info"], error_spec(case, metric), h_points(case, metric)) for case in members]
    curves = [c for c in curves if c[1] is not None and len(c[2]) >= 2]
    if len(curves) < 2:
        return None
    resolution = common_text(info.get("resolution", {}).get("name") for info, _, _ in curves)
    unit = common_text(spec.get("unit") for _, spec, _ in curves)
    fig, ax = writer.figure(f"{group}: {metric}, error vs h",
                            "h" + (f"  ({resolution})" if resolution else ""),
                            f"{metric} error" + (f" ({unit})" if unit else ""))
    ax.set_xscale("log")
    ax.set_yscale("log")
    writer.log_axis(ax.xaxis)
    writer.log_axis(ax.yaxis)
    triangles = {}  # theoretical order -> (points, color) of the case with the lowest finest error
    for index, (info, spec, points) in enumerate(curves):
        color = f"C{index % 10}"
        theory = spec.get("theoretical_order")
        label = member_label(info, group, 66)
        if finite(theory) and theory > 0:
            label += f" (theory {theory:g})"
            # Under the lowest line of that order, the triangle stays clear of the others.
            if theory not in triangles or min(points)[1] < min(triangles[theory][0])[1]:
                triangles[theory] = (points, color)
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=color, markersize=4,
                linewidth=1.2, label=label)
    # More than a few orders would clutter the figure; the legend carries each case's order.
    if len(triangles) > 3:
        triangles = {}
    for theory, (points, color) in triangles.items():
        slope_triangle(ax, points, theory, color)
    thin_log_ticks(writer, ax)
    legend_below(fig, ax)
    file = writer.save(fig, stem)
    names = ", ".join(info["name"] for info, _, _ in curves)
    caption = (f"{metric}: error vs h across group {group}, one line per case, a marker per level "
               f"(cases: {names})")
    if triangles:
        caption += "; triangles: theoretical slope " + ", ".join(f"{t:g}" for t in triangles)
    return {"file": file, "caption": caption}


def work_clock(members, metric):
    """"cpu" if every level with an error of `metric` records a CPU time, else "wall": one
    clock per figure."""
    levels = [level for case in members for level, _ in error_levels(case, metric)]
    return "cpu" if levels and all(level_seconds(l, "cpu") is not None for l in levels) else "wall"


def group_work_plot(writer, group, metric, members, stem, note):
    """Work-precision: error of `metric` vs the time per level for the member cases, one line
    each, levels coarse to fine."""
    clock = work_clock(members, metric)
    curves = [(case["info"], error_spec(case, metric), time_points(case, metric, clock))
              for case in members]
    curves = [c for c in curves if c[1] is not None and len(c[2]) >= 2]
    if len(curves) < 2:
        return None
    clock_name = "CPU" if clock == "cpu" else "wall-clock"
    unit = common_text(spec.get("unit") for _, spec, _ in curves)
    fig, ax = writer.figure(f"{group}: {metric}, work-precision",
                            f"{clock_name} time per level (s, single run)",
                            f"{metric} error" + (f" ({unit})" if unit else ""))
    ax.set_xscale("log")
    ax.set_yscale("log")
    writer.log_axis(ax.xaxis)
    writer.log_axis(ax.yaxis)
    label_levels = len(curves) <= 3
    for index, (info, spec, points) in enumerate(curves):
        color = f"C{index % 10}"
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=color, markersize=4,
                linewidth=1.2, label=member_label(info, group))
        if label_levels:
            resolution = info.get("resolution", {}).get("name", "")
            for k, (seconds, error, value) in enumerate(points):
                if finite(value):
                    text = f"{resolution}={value:g}" if k == 0 and resolution else f"{value:g}"
                    ax.annotate(text, (seconds, error), xytext=(4, 2), textcoords="offset points",
                                fontsize=6, color=color)
    thin_log_ticks(writer, ax)
    legend_below(fig, ax)
    file = writer.save(fig, stem)
    names = ", ".join(info["name"] for info, _, _ in curves)
    caption = (f"{metric}: work-precision across group {group}, error vs {clock_name} time per "
               f"level, one line per case, a marker per level"
               + (" (labelled with its resolution)" if label_levels else "")
               + f"; the line further left at a given error reaches it cheaper (cases: {names}). "
               f"Times are single-run {clock_name} measurements of the whole level (solve and "
               f"error evaluation) {note}, so short times are noisy")
    return {"file": file, "caption": caption}


def plan(cases):
    """The plot jobs in manifest order: one per case, then one per group overlay, then per group
    of two or more cases and shared error metric its error-vs-h and work-precision figures. File
    stems are made unique here, so parallel workers never write the same file."""
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
    by_group = {}  # group -> [case index], in case order
    for index, case in enumerate(cases):
        group = case["info"].get("group")
        if isinstance(group, str) and group:
            by_group.setdefault(group, []).append(index)
    for group, members in by_group.items():
        if len(members) < 2:
            continue
        for metric, indices in shared_error_metrics(cases, members):
            stem = f"group-{slugify(group)}-{slugify(metric)}"
            drawn = [i for i in indices if len(h_points(cases[i], metric)) >= 2]
            if len(drawn) >= 2:
                group_jobs.append(("group-error", group, metric, drawn, unique(stem + "-vs-h")))
            clock = work_clock([cases[i] for i in indices], metric)
            timed = [i for i in indices if len(time_points(cases[i], metric, clock)) >= 2]
            if len(timed) >= 2:
                group_jobs.append(("group-work", group, metric, timed,
                                   unique(stem + "-work-precision")))
    return case_jobs + group_jobs


_STATE = {}  # cases, writer and timing note, set before the worker processes are forked


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
    if job[0] in ("group-error", "group-work"):
        _, group, metric, members, stem = job
        members = [cases[index] for index in members]
        if job[0] == "group-error":
            entry = group_error_plot(writer, group, metric, members, stem)
        else:
            entry = group_work_plot(writer, group, metric, members, stem, _STATE["timing_note"])
        return [entry] if entry else []
    _, group, series_name, members, stem = job
    pairs = []
    for index in members:
        case = cases[index]
        level = finest_level(case)
        series = next(s for s in level["series"] if s["name"] == series_name)
        pairs.append((case["info"], series))
    entry = group_plot(writer, group, series_name, pairs, stem)
    return [entry] if entry else []


class Progress:
    """Figures drawn so far, on the stream rodvv passes as --progress-fd (its own stderr): a bar
    redrawn in place on a terminal, a line per quarter otherwise (CI logs)."""

    def __init__(self, fd, total):
        self.total, self.done, self.quarter = total, 0, 0
        self.stream = None
        if fd is not None:
            try:
                self.stream = os.fdopen(fd, "w", buffering=1, closefd=False)
                self.tty = self.stream.isatty()
            except OSError:
                self.stream = None

    def step(self):
        if self.stream is None or self.total == 0:
            return
        self.done += 1
        if self.tty:
            width = 30
            filled = width * self.done // self.total
            self.stream.write(f"\rplots: [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} jobs")
            if self.done == self.total:
                self.stream.write("\n")
        elif 4 * self.done >= (self.quarter + 1) * self.total:
            self.quarter = 4 * self.done // self.total
            self.stream.write(f"plots: {self.done}/{self.total} jobs\n")
        self.stream.flush()


def run_jobs(jobs, progress):
    """In parallel over the CPUs this process may use (fork keeps the loaded results shared);
    serially for a handful of jobs or where processes cannot be forked. Results in job order."""
    try:
        workers = min(len(os.sched_getaffinity(0)), MAX_WORKERS)
    except AttributeError:
        workers = 1
    if workers > 1 and len(jobs) >= 8:
        try:
            context = multiprocessing.get_context("fork")
            with concurrent.futures.ProcessPoolExecutor(workers, mp_context=context) as pool:
                results = []
                for entries in pool.map(run_job, jobs, chunksize=2):
                    results.append(entries)
                    progress.step()
                return results
        except (OSError, concurrent.futures.process.BrokenProcessPool):
            progress.done = 0
    results = []
    for job in jobs:
        results.append(run_job(job))
        progress.step()
    return results


def main(argv):
    progress_fd = None
    if len(argv) == 4 and argv[3].startswith("--progress-fd="):
        try:
            progress_fd = int(argv[3].split("=", 1)[1])
        except ValueError:
            progress_fd = None
        argv = argv[:3]
    if len(argv) != 3:
        print("usage: plot_results.py results.json OUTDIR/plots [--progress-fd=N]", file=sys.stderr)
        return 2
    results_path, outdir = argv[1], argv[2]
    try:
        document = load(results_path)
        cases = document["cases"]
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
    _STATE["timing_note"] = timing_note(document)
    _STATE["writer"] = PlotWriter(plt, ticker, outdir)

    manifest = {"cases": {}, "groups": {}}
    try:
        jobs = plan(cases)
        for job, entries in zip(jobs, run_jobs(jobs, Progress(progress_fd, len(jobs)))):
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
