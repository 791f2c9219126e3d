#pragma once
// What the trefoil cases of both rods share: the rod and its pull (parameters B, C, T), and what they
// measure on their solution struct: H through the knot, the 3-D Noether metrics, and the loose-knot
// relations of the loop (PHYSICS.md §5.1, the tension elastica homoclinic). The rod-specific metrics
// (contacts, iterations) and parameters (looseness, barrier windows) are each case's own.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "../case_builder.hpp"
#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/parameters.hpp"

namespace rodvv::harness::knot_cases {

// The knot both rods tie: bending B (EI1 = EI2), twisting C (GJ), the dead pull T, the looseness
// h sqrt(T/B) and the barrier's stiffness in the rod's own units (each rod's barrier parameter says which).
struct TrefoilKnot {
  double B = 0.0, C = 0.0, T = 0.0, looseness = 0.0, barrier = 0.0;
  double lambda() const;  // sqrt(B/T), the loop's scale
  double radius() const;  // h = looseness lambda
};
// From the parameters B, C, T, radius (h: looseness = radius sqrt(T/B)) and barrier; looseness and barrier may be
// given instead (a sweep over one of them, whose level is not a parameter).
TrefoilKnot trefoil_knot(const Parameters& p, std::optional<double> looseness = std::nullopt,
                         std::optional<double> barrier = std::nullopt);

struct LoopRelations {
  double perpendicular_ratio = 0.0;  // mean 1/2 B kappa^2 / T where t.e_x changes sign (loose limit 1)
  std::size_t perpendicular_points = 0;
  double apex_ratio = 0.0;  // B kappa_apex^2 / (4 T) (loose limit 1)
};

// At the stations where the tangent turns through perpendicular to the pull e_x (t.e_x changes sign;
// kappa interpolated linearly in t.e_x), and at the apex of the loop: the station between the first
// and the last of them whose tangent points most against the pull. kappa = |(u1, u2)| (u0 = twist).
// SolverError(method, ...) with the solve's iterations and residual when there is no loop (fewer
// than 2 such points).
LoopRelations loop_relations(const SpatialRodSolution& solution, double B, double T, const std::string& method,
                             std::size_t iterations, double residual);

// The solve that produced a trefoil's solution struct, for the error a lost loop reports.
struct TrefoilSolve {
  std::string method;
  std::size_t iterations = 0;
  double residual = 0.0;
};

// H_deviation = max_s |H(s) - T| / T (flattened form), the Noether metrics with H = T exact, the loop
// relations, and the end shortening (L - span) / (4 sqrt(B/T)), span = the ends' distance along the pull.
void add_trefoil_metrics(LevelOutput& output, const SpatialRodSolution& solution, double B, double T, double span,
                         const TrefoilSolve& solve);
// Their specs, in that order.
std::vector<MetricSpec> trefoil_metric_specs();

// B = 1.3 (EI1 = EI2), C = 0.9 (GJ), T = 5.2 (the dead pull), each in (0, 1e12], then the case's own
// (radius, barrier).
Parameters trefoil_parameters(std::vector<Parameter> own);

// The rod's radius h (a length; default 0.05: looseness 0.1 at the default B and T).
Parameter radius_parameter();
// The looseness h sqrt(T/B) in [low, high] (measured per rod); InputError naming radius otherwise.
cases::Window looseness_window(double low, double high, std::string why);

// The regression tolerance (Case::golden_absolute) of the hard trefoils' overlap_over_tolerance, the deepest
// overlap over the statics' gap tolerance. It is round-off, whose bits follow the CPU (case.hpp): measured
// 1.4e-8 on the nodal rod, 1.6e-7 .. 1e-6 on the Super-Helix (1.6e-7 against 3.0e-7 at N = 100 on two CPUs).
// 1e-3: a thousand times the largest measured and a thousandth of the overlap gate's 1.
inline constexpr double kOverlapGoldenTolerance = 1e-3;

}  // namespace rodvv::harness::knot_cases
