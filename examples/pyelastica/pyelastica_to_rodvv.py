#!/usr/bin/env python3
"""Convert a planar PyElastica rod state to a rodvv solution file (README, "Checking your own solver").

PyElastica (GazzolaLab, MIT) discretises a Cosserat rod on a staggered grid: positions on the N + 1
nodes, directors and the internal force on the N elements, curvature and couple on the N - 1
interior (Voronoi) nodes. rodvv's planar format has every array on the nodes, so this converter
moves the element and Voronoi values there, with rules that are second order in the element length
and use nothing about the problem's answer:

  theta   angle of the element's d3 (the section director) in the x-y plane; at an interior node the
          mean of its two elements, at an end node its one element;
  kappa   PyElastica's kappa about d2 (= e_z for a rod in the x-y plane with d1 in the plane), per
          rest length; at the two end nodes linear extrapolation from the two nearest Voronoi nodes;
  n       the lab-frame internal force Q^T n_L / e of each element (PyElastica's
          _compute_internal_forces); at a node the mean of its elements, at an end its one element;
  EI      bend_matrix about d2 on the Voronoi nodes, extended to the ends; EA and GA (alpha_c G A)
          from shear_matrix, which must be uniform.

Input: the JSON written by PyElastica runs (one static state; `state` holds PyElastica's arrays under
their own names, `problem` the rod and its load; see tests/data/pyelastica/README.md).

    pyelastica_to_rodvv.py STATE.json [STATE.json ...] --out DIR [--case CASE]

CASE is elastica/mattiasson-<P L^2/EI> by default (the inextensible elastica; parameters L, EI, alpha),
or elastica/reissner-cantilever (the extensible, shearable rod at the state's own EA and GA;
parameters L, EI, P, EA, GA).
"""
import argparse
import json
import math
import os
import sys


def fail(path, message):
    sys.exit(f"pyelastica_to_rodvv: {path}: {message}")


def convert(path, case_name):
    with open(path) as stream:
        data = json.load(stream)
    state, problem, provenance = data["state"], data["problem"], data.get("provenance", {})
    position, director = state["position_collection"], state["director_collection"]
    n = len(state["rest_lengths"])
    if len(position[0]) != n + 1:
        fail(path, f"{len(position[0])} nodes for {n} elements")
    # Planar in x-y: every z and every out-of-plane director component ~ 0.
    if max(abs(z) for z in position[2]) > 1e-9 * problem["L"]:
        fail(path, "the rod leaves the x-y plane; this converter handles planar states only")

    s = [0.0]
    for length in state["rest_lengths"]:
        s.append(s[-1] + length)

    # Element angles from d3 = director_collection[2, :, k] (rows of Q are d1, d2, d3).
    element_theta = [math.atan2(director[2][1][k], director[2][0][k]) for k in range(n)]
    theta = [element_theta[0]] + [0.5 * (element_theta[k - 1] + element_theta[k]) for k in range(1, n)] + [
        element_theta[-1]]

    # Curvature on the Voronoi nodes 1 .. N-1, about d2. PyElastica's d2 = d3 x d1 is +e_z here (d1 in
    # the plane), so kappa[1] is theta' with rodvv's sign (counter-clockwise positive). Checked
    # against the element angles, so that a flipped frame cannot pass silently.
    voronoi_kappa = state["kappa"][1]
    for k in range(1, n):
        difference = (element_theta[k] - element_theta[k - 1]) / state["rest_voronoi_lengths"][k - 1]
        if abs(difference - voronoi_kappa[k - 1]) > 1e-6 * (1.0 + abs(difference)):
            fail(path, f"kappa about d2 at node {k} is {voronoi_kappa[k - 1]}, the element angles give "
                       f"{difference}: the frame is not d1 in the plane, d2 = e_z")

    def extrapolate(s0, s1, f0, f1, at):
        return f0 + (f1 - f0) * (at - s0) / (s1 - s0)

    if n >= 3:
        kappa = ([extrapolate(s[1], s[2], voronoi_kappa[0], voronoi_kappa[1], s[0])] + list(voronoi_kappa) +
                 [extrapolate(s[n - 2], s[n - 1], voronoi_kappa[-2], voronoi_kappa[-1], s[n])])
    else:
        kappa = [voronoi_kappa[0]] * (n + 1)

    # Lab-frame internal force of each element: Q^T n_L / e (n_L in material components).
    stress, dilatation = state["internal_stress"], state["dilatation"]
    element_force = []
    for k in range(n):
        lab = [sum(director[i][j][k] * stress[i][k] for i in range(3)) / dilatation[k] for j in range(3)]
        element_force.append(lab)

    def on_nodes(values):
        return [values[0]] + [0.5 * (values[k - 1] + values[k]) for k in range(1, n)] + [values[-1]]

    force_x = on_nodes([f[0] for f in element_force])
    force_y = on_nodes([f[1] for f in element_force])

    bend = [state["bend_matrix"][1][1][k] for k in range(n - 1)]
    bending_stiffness = [bend[0]] + bend + [bend[-1]]
    shear = state["shear_matrix"]
    ea, ga = shear[2][2][0], shear[0][0][0]
    for k in range(n):
        if shear[2][2][k] != ea or shear[0][0][k] != ga or shear[1][1][k] != ga:
            fail(path, f"shear_matrix differs between elements (element {k}); a uniform rod is expected")

    load = -problem["load_vector"][1]
    alpha = load * problem["L"] ** 2 / problem["EI"]
    case_name = case_name or f"elastica/mattiasson-{alpha:g}"
    if case_name.startswith("elastica/reissner-cantilever"):
        # The extensible, shearable cantilever: the rod's own EA and GA, the load itself.
        parameters = {"L": problem["L"], "EI": problem["EI"], "P": load, "EA": ea, "GA": ga}
    else:
        # The inextensible elastica: the load parameter only (EA, GA ~ 1e5 are PyElastica's stand-in).
        parameters = {"L": problem["L"], "EI": problem["EI"], "alpha": alpha}
    solver = "PyElastica {} ({} at {}), {}".format(provenance.get("elastica_version", "?").split(" ")[0],
                                                   provenance.get("source_repo", "?"),
                                                   provenance.get("source_commit", "?")[:12],
                                                   provenance.get("stepper", "?"))
    return {
        "format": "rodvv-solution",
        "version": 1,
        "case": case_name,
        "parameters": parameters,
        "resolution": {"N": n},
        "solver": solver,
        # PyElastica's time-stepping loop to rest (the provenance's loop_cpu_s, loop_wall_s).
        "cpu_seconds": provenance.get("loop_cpu_s", 0.0),
        "wall_seconds": provenance.get("loop_wall_s", 0.0),
        "planar_rod": {
            "length": s[-1],
            "axial_stiffness": ea,
            "shear_stiffness": ga,
            "nodes": {
                "s": s, "x": position[0], "y": position[1], "theta": theta, "kappa": kappa,
                "force_x": force_x, "force_y": force_y, "bending_stiffness": bending_stiffness,
            },
        },
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("states", nargs="+", help="PyElastica state files (JSON)")
    parser.add_argument("--out", required=True, help="output directory for the rodvv solution files")
    parser.add_argument("--case", help="rodvv case or group (default elastica/mattiasson-<P L^2/EI>)")
    arguments = parser.parse_args()
    if not os.path.isdir(arguments.out):
        sys.exit(f"pyelastica_to_rodvv: --out {arguments.out}: not a directory")
    for path in arguments.states:
        solution = convert(path, arguments.case)
        target = os.path.join(arguments.out, os.path.basename(path))
        with open(target, "w") as stream:
            json.dump(solution, stream)
        print(f"{path} -> {target} (N = {solution['resolution']['N']})")


if __name__ == "__main__":
    main()
