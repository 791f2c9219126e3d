#pragma once
// The rodvv solution-file format: one solution of one case at one resolution, written by any solver
// and read by `rodvv check` (README, "Checking your own solver"). JSON, format "rodvv-solution",
// version 1; the per-node (or per-sample) arrays inline or in a CSV file beside it.
//
//   {
//     "format": "rodvv-solution", "version": 1,
//     "case": "elastica/mattiasson-2",          a case name or its group (rodvv list)
//     "parameters": {"L": 1.0, "EI": 1.0},      the case parameters used (others: the case's defaults)
//     "resolution": {"N": 40},                  the case's resolution parameter and its value
//     "solver": "PyElastica 1.0.0, ...",        free text, shown in the report
//     "cpu_seconds": 37.8, "wall_seconds": 37.8 optional: the solver's cost, for work-precision plots
//     "planar_rod": {...}, "spatial_rod": {...}, "trajectory": {...} or "rod_trajectory": {...}
//   }
//
// Units are the case's parameter units (rodvv list -v); angles in radians.
//
// planar_rod: nodes i = 0 .. N in arrays (PlanarRodSolution's conventions, planar_rod.hpp), inline
// under "nodes" or as the columns of "nodes_csv" (a path relative to the JSON file, a header row of
// column names):
//   s, x, y                     required: arclength (strictly increasing) and position
//   theta, kappa                tangent angle, curvature; derived from x, y (and theta) when absent
//   force_x, force_y            internal force n (the action of (s, L] on [0, s]); absent: no H
//   axial_force, shear_force    n.t and n.N; derived from n and theta when absent
//   bending_stiffness           EI per node; or a number beside "nodes" (uniform); absent: no H
//   natural_curvature, potential    0 when absent
// and beside "nodes": "length" (default s[N]), "axial_stiffness" / "shear_stiffness" (EA, GA;
// absent = rigid), "iterations", "residual".
//
// trajectory: "t", "theta", "theta_dot" inline under "samples" or in "samples_csv"; t strictly
// increasing; optional "steps" and "rhs_evaluations".
//
// rod_trajectory (a 3-D rod in time, RodTrajectory of rod_trajectory.hpp): one row per vertex and
// snapshot in "t", "s", "position_x", "position_y", "position_z", inline under "samples" or in
// "samples_csv"; a snapshot's rows together (equal t, s strictly increasing from 0), the snapshots in
// strictly increasing t; optional "steps".
//
// Every malformed file is an InputError naming the file, the JSON path (or CSV line and column) and
// what was expected; nothing in a file can crash the reader or make it allocate beyond the file's
// own size.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rodvv/common/solution.hpp"

namespace rodvv::solution_files {

inline constexpr const char* kFormatName = "rodvv-solution";
inline constexpr int kFormatVersion = 1;

struct SolutionFile {
  std::string source;                                     // the file it was read from
  std::string case_name;                                  // as written: a case or a group name
  std::vector<std::pair<std::string, double>> parameters; // in file order
  std::string resolution_name;                            // "N", "dt"
  double level = 0.0;
  std::string solver;
  double cpu_seconds = 0.0;   // the solver's cost of this solution, when the file states it (else 0)
  double wall_seconds = 0.0;
  Solution solution;
  std::vector<std::string> derived;  // what the reader derived, and how ("theta from x, y: ...")
  std::vector<std::string> missing;  // what is absent and what it costs ("force_x, force_y: no H")
};

// `source` names the text in messages; `directory` resolves a relative *_csv path.
SolutionFile parse_solution(std::string_view json_text, const std::string& source,
                            const std::filesystem::path& directory);
SolutionFile read_solution_file(const std::filesystem::path& path);

// The JSON text of a solution file (arrays inline, doubles in shortest round-trip form, so reading
// it back gives the same bits).
std::string format_solution(const SolutionFile& file);
void write_solution_file(const std::filesystem::path& path, const SolutionFile& file);

}  // namespace rodvv::solution_files
