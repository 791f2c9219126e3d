#include "continuous_rest_strain.hpp"

#include <array>

#include <Eigen/Geometry>
#include <boost/numeric/odeint.hpp>

namespace rodvv::harness::inverse_cases {

namespace {
// R (9, row-major), r (3), P (3).
using State = std::array<double, 15>;
namespace odeint = boost::numeric::odeint;

Mat3 frame_of(const State& y) {
  Mat3 R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R(i, j) = y[std::size_t(3 * i + j)];
  return R;
}
Vec3 vector_at(const State& y, std::size_t offset) { return Vec3(y[offset], y[offset + 1], y[offset + 2]); }

struct Sample {
  Mat3 R;
  Vec3 r, P;
};
}  // namespace

std::vector<Vec3> continuous_rest_strain(const ContinuousRod& rod, const std::vector<double>& stations) {
  auto rhs = [&rod](const State& y, State& dy, double s) {
    const Mat3 R = frame_of(y);
    const Vec3 k = rod.strain(s);
    Mat3 K;
    K << 0.0, -k.z(), k.y(), k.z(), 0.0, -k.x(), -k.y(), k.x(), 0.0;
    const Mat3 dR = R * K;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) dy[std::size_t(3 * i + j)] = dR(i, j);
    for (int i = 0; i < 3; ++i) {
      dy[std::size_t(9 + i)] = R(i, 0);                  // r' = R e0
      dy[std::size_t(12 + i)] = y[std::size_t(9 + i)];  // P' = r
    }
  };
  State y{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) y[std::size_t(3 * i + j)] = rod.root_frame(i, j);
    y[std::size_t(9 + i)] = rod.root_position[i];
  }
  std::vector<double> times{0.0};
  times.insert(times.end(), stations.begin(), stations.end());
  times.push_back(rod.length);
  std::vector<Sample> samples;
  samples.reserve(times.size());
  auto stepper = odeint::make_controlled(1e-14, 1e-14, odeint::runge_kutta_fehlberg78<State>());
  odeint::integrate_times(stepper, rhs, y, times.begin(), times.end(), 1e-3 * rod.length,
                          [&samples](const State& state, double) {
                            samples.push_back({frame_of(state), vector_at(state, 9), vector_at(state, 12)});
                          });
  const Sample& end = samples.back();
  const Vec3 weight = rod.line_density * rod.gravity;
  std::vector<Vec3> rest;
  rest.reserve(stations.size());
  for (std::size_t k = 0; k < stations.size(); ++k) {
    const Sample& at = samples[k + 1];
    const double s = stations[k];
    const Vec3 m = ((end.P - at.P) - (rod.length - s) * at.r).cross(weight) + (end.r - at.r).cross(rod.end_force) +
                   rod.end_moment;
    rest.push_back(rod.strain(s) - (at.R.transpose() * m).cwiseQuotient(rod.stiffness));
  }
  return rest;
}

}  // namespace rodvv::harness::inverse_cases
