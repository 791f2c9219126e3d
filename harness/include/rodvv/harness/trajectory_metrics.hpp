#pragma once
// Metrics read off a time trajectory (the harness's side of "invariants and metrics are functions
// of solution structs only").
#include <cstddef>
#include <vector>

#include "rodvv/common/trajectory.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

// Times where theta(t) crosses one of the values offset + j * spacing (j integer; spacing = 0
// means the single value offset), in either direction. Each crossing is located on the cubic
// Hermite interpolant through (theta, theta') at the two bracketing samples, so the location
// error is O(dt^4) and does not pollute the order of methods up to fourth order.
std::vector<double> crossing_times(const Trajectory& trajectory, double offset, double spacing);

// Mean period from equally spaced crossing times: (t_last - t_first) / (count - 1) times the
// number of crossings per period. Empty when there are fewer than two crossings.
std::optional<double> period_from_crossings(const std::vector<double>& times,
                                            double crossings_per_period);

// Sample indices at which a solution is compared with its reference: every stride-th sample plus
// the last, with stride a power of two chosen so that at most ~max_points are compared. With
// levels refined by factors of two the compared times coincide across levels.
std::vector<std::size_t> comparison_indices(std::size_t samples, std::size_t max_points = 2048);

// Thins a curve to at most max_points by keeping, in each of max_points bins, the sample of
// largest |y| (so peaks survive for plots).
Series thin_series(std::string name, std::string x_label, std::string y_label,
                   const std::vector<double>& x, const std::vector<double>& y,
                   std::size_t max_points = 400);

}  // namespace rodvv::harness
