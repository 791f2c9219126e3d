#pragma once
// The measurement and the gates the manufactured-solution cases of both 3-D rods share
// (rod3d/manufactured, superhelix/manufactured; references/manufactured_rod.hpp): each metric the largest
// deviation of a solution from the manufactured fields - vertex positions / L, station frames (rotation
// angle), strains u L, internal force n / max |n|, moment m / max |m| - read from the solution only, so
// that another solver's file is measured like rodvv's own.
#include <string>
#include <utility>
#include <vector>

#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/references/manufactured_rod.hpp"

namespace rodvv::harness::cases {

LevelOutput measure_manufactured(const SpatialRodSolution& solution, const references::ManufacturedRod& exact);

std::vector<MetricSpec> manufactured_metric_specs();

// What another solver needs to pose the manufactured problem (`rodvv problem`): the clamp, the stiffness and
// natural strain, the tip loads n(L), m(L), the force and couple densities at the stations s, and the exact
// solution there.
ProblemData manufactured_problem_data(const references::ManufacturedRod& rod, const std::vector<double>& s);

// An order gate and a bound C h^2 (C = 2 x the value measured at the finest default level) per metric.
std::vector<GateSpec> manufactured_gates(const std::vector<std::pair<std::string, double>>& measured_at_finest,
                                         double h_finest, const std::string& why_second_order);

}  // namespace rodvv::harness::cases
