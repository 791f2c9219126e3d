#!/usr/bin/python3
"""The group comparison figures of reports/plot_results.py on a small synthetic results.json.

    /usr/bin/python3 test_plot_groups.py PATH/TO/plot_results.py

A group of two or more cases gets, per error metric that at least two of them can draw, an
error-vs-h and a work-precision figure; a group of one case, a metric only one case has and a
shared invariant get none. A series labelled "levels: ..." gathers one point from every level (a
law over a parameter the levels vary), the other series of the figure come from the finest level. Prints "skipped" and exits 0 when matplotlib is missing (as the C++
plot tests skip).
"""

import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = None


def level(h, errors, wall, cpu=None):
    out = {"level": 1.0 / h, "h": h, "wall_seconds": wall, "failure": None, "series": [],
           "metrics": {name: {"value": e, "reference": 0.0, "error": e} for name, e in errors.items()}}
    if cpu is not None:
        out["cpu_seconds"] = cpu
    return out


def case(name, group, order, scale, cpu=False, extra_metric=None):
    metrics = [{"name": "tip", "kind": "error", "unit": "length", "description": "tip error",
                "extrapolate": True, "theoretical_order": order},
               {"name": "drift", "kind": "invariant", "unit": "", "description": "drift",
                "extrapolate": False, "theoretical_order": None}]
    if extra_metric:
        metrics.append({"name": extra_metric, "kind": "error", "unit": "", "description": "",
                        "extrapolate": False, "theoretical_order": None})
    levels = []
    for k, h in enumerate((0.1, 0.05, 0.025)):
        errors = {"tip": scale * h ** order, "drift": 1e-3 * h}
        if extra_metric:
            errors[extra_metric] = 1e-4 * h
        wall = 1e-3 * 2 ** k
        levels.append(level(h, errors, wall, cpu=0.9 * wall if cpu else None))
    return {"info": {"name": name, "family": "demo", "group": group, "title": name,
                     "method": f"method of {name}", "metrics": metrics,
                     "resolution": {"name": "N", "description": "elements", "scale": "count",
                                    "default_levels": [10, 20, 40], "extended_levels": []}},
            "levels": levels, "analyses": [], "gates": [], "skipped_gates": [],
            "wall_seconds": 0.01}


def law_case():
    """Levels that each add one measured point to a law, drawn over the finest level's curve."""
    out = case("demo/law/over-levels", "demo/law", 2.0, 1.0)
    for k, lvl in enumerate(out["levels"]):
        lvl["series"] = [{"name": "law|curve", "x_label": "a", "y_label": "b",
                          "x": [0.0, 1.0, 2.0, 3.0], "y": [0.0, 1.0, 4.0, 9.0]},
                         {"name": "law|levels: measured", "x_label": "a", "y_label": "b",
                          "x": [float(k + 1)], "y": [float((k + 1) ** 2) * 1.01]}]
    return out


def parameter_case():
    """A parameter study: its levels are angles, not meshes."""
    out = case("demo/angles/study", "demo/angles", 2.0, 1.0)
    out["info"]["resolution"].update({"name": "angle", "scale": "parameter", "default_levels": [10, 20, 30]})
    for lvl, angle in zip(out["levels"], (10.0, 20.0, 30.0)):
        lvl["level"] = angle
    return out


def results():
    return {"schema_version": 1, "merged_from": [], "passed": True,
            "provenance": {"cpu_model": "Test CPU", "host_cores": 2, "build_type": "Release"},
            "cases": [case("demo/two/nodal", "demo/two", 2.0, 1.0, extra_metric="only-here"),
                      case("demo/two/reduced", "demo/two", 4.0, 3.0),
                      case("demo/one/alone", "demo/one", 2.0, 1.0),
                      case("demo/cpu/a", "demo/cpu", 2.0, 1.0, cpu=True),
                      case("demo/cpu/b", "demo/cpu", 2.0, 2.0, cpu=True), law_case(), parameter_case()]}


class GroupFigures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        path = os.path.join(cls.tmp.name, "results.json")
        with open(path, "w", encoding="utf-8") as stream:
            json.dump(results(), stream)
        cls.plots = os.path.join(cls.tmp.name, "plots")
        run = subprocess.run([sys.executable, SCRIPT, path, cls.plots], capture_output=True,
                             text=True, check=False)
        if run.returncode != 0:
            raise AssertionError(f"plot_results.py exited {run.returncode}: {run.stderr}")
        with open(os.path.join(cls.plots, "manifest.json"), encoding="utf-8") as stream:
            cls.manifest = json.load(stream)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def files(self, group):
        return [entry["file"] for entry in self.manifest["groups"].get(group, [])]

    def test_two_case_group_gets_error_and_work_precision_figures(self):
        self.assertEqual(self.files("demo/two"), ["plots/group-demo-two-tip-vs-h.png",
                                                  "plots/group-demo-two-tip-work-precision.png"])
        for file in self.files("demo/two"):
            self.assertGreater(os.path.getsize(os.path.join(self.tmp.name, file)), 1000, file)

    def test_one_case_group_gets_none(self):
        self.assertNotIn("demo/one", self.manifest["groups"])
        self.assertFalse(any(name.startswith("group-demo-one") for name in os.listdir(self.plots)))

    def test_captions_name_the_cases_and_the_clock(self):
        entries = self.manifest["groups"]["demo/two"]
        self.assertIn("demo/two/nodal, demo/two/reduced", entries[0]["caption"])
        self.assertIn("theoretical slope 2, 4", entries[0]["caption"])
        work = entries[1]["caption"]
        self.assertIn("wall-clock time per level", work)
        self.assertIn("single-run", work)
        self.assertIn("Test CPU", work)
        cpu = self.manifest["groups"]["demo/cpu"][1]
        self.assertEqual(cpu["file"], "plots/group-demo-cpu-tip-work-precision.png")
        self.assertIn("CPU time per level", cpu["caption"])

    def test_cases_keep_their_own_figures(self):
        self.assertEqual(self.manifest["cases"]["demo/one/alone"][0]["file"],
                         "plots/demo-one-alone-convergence.png")

    def test_a_levels_series_is_drawn_from_every_level(self):
        files = [entry for entry in self.manifest["cases"]["demo/law/over-levels"]
                 if "series-law" in entry["file"]]
        self.assertEqual(len(files), 1)
        self.assertIn("the markers: every level", files[0]["caption"])
        self.assertGreater(os.path.getsize(os.path.join(self.tmp.name, files[0]["file"])), 1000)

    def test_a_parameter_study_is_drawn_over_its_levels_without_slopes(self):
        entry = self.manifest["cases"]["demo/angles/study"][0]
        self.assertIn("no order is fitted", entry["caption"])
        self.assertGreater(os.path.getsize(os.path.join(self.tmp.name, entry["file"])), 1000)
        spec = importlib.util.spec_from_file_location("plot_results", SCRIPT)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker as ticker
        writer = module.PlotWriter(plt, ticker, self.plots)
        drawn = {}

        def keep(fig, name):
            drawn["lines"] = {line.get_label(): list(line.get_xdata()) for line in fig.axes[0].get_lines()}
            drawn["xscale"] = fig.axes[0].get_xscale()
            plt.close(fig)
            return name

        writer.save = keep
        module.convergence_plot(writer, parameter_case(), "angles")
        self.assertEqual(drawn["lines"]["tip"], [10.0, 20.0, 30.0])  # over the angle, not h = 1 / angle
        self.assertEqual(drawn["xscale"], "linear")
        self.assertFalse(any("fit" in label or "slope" in label for label in drawn["lines"]))
        module.convergence_plot(writer, case("demo/mesh", "demo/mesh", 2.0, 1.0), "mesh")
        self.assertEqual(drawn["xscale"], "log")  # a mesh study keeps its log-log figure

    def test_gathering_takes_each_levels_points_in_order_and_leaves_other_series(self):
        spec = importlib.util.spec_from_file_location("plot_results", SCRIPT)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        law = law_case()
        finest = law["levels"][-1]["series"]
        gathered = module.gathered_over_levels(law, finest[1])
        self.assertEqual(gathered["x"], [1.0, 2.0, 3.0])
        self.assertEqual(gathered["y"], [1.01, 4.04, 9.09])
        self.assertIs(module.gathered_over_levels(law, finest[0]), finest[0])


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: test_plot_groups.py PATH/TO/plot_results.py", file=sys.stderr)
        sys.exit(2)
    SCRIPT = os.path.abspath(sys.argv.pop(1))
    try:
        import matplotlib  # noqa: F401  (the script under test needs it)
    except ImportError:
        print(f"skipped: matplotlib is not available for {sys.executable}")
        sys.exit(0)
    unittest.main(verbosity=2)
