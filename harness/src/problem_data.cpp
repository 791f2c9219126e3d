#include "rodvv/harness/problem_data.hpp"

namespace rodvv::harness {

std::vector<double> uniform_stations(double length, std::size_t intervals) {
  std::vector<double> s(intervals + 1);
  for (std::size_t i = 0; i < intervals; ++i) s[i] = length * double(i) / double(intervals);
  s[intervals] = length;
  return s;
}

}  // namespace rodvv::harness
