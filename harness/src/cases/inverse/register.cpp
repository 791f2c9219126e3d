// inverse/*: inverse statics. One file per problem in this folder; this one lists them.
#include "inverse_cases.hpp"

namespace rodvv::harness {

void register_inverse_cases(Registry& registry) {
  inverse_cases::add_round_trip(registry);
  inverse_cases::add_stability_threshold(registry);
  inverse_cases::add_round_trip_sphere(registry);
  inverse_cases::add_curve_fit(registry);
  inverse_cases::add_capstan(registry);
  inverse_cases::add_bundle(registry);
  inverse_cases::add_friction_cone(registry);
  inverse_cases::add_incline_sliding(registry);
  inverse_cases::add_hanging_fold(registry);
}

}  // namespace rodvv::harness
