#pragma once
// inverse/*: inverse statics of the Super-Helix (solvers/superhelix/inverse_statics.hpp; ALGORITHMS.md
// §3): the rest shape that makes a given shape a (stable) equilibrium. One problem per file here;
// register.cpp lists them.
#include "rodvv/harness/registry.hpp"

namespace rodvv::harness::inverse_cases {

void add_round_trip(Registry& registry);           // round-trip-planar, round-trip-3d
void add_stability_threshold(Registry& registry);  // Greenhill's heavy column, statics and dynamics
void add_round_trip_sphere(Registry& registry);    // frictional contact: the SOCQP of the 2013 paper
void add_curve_fit(Registry& registry);            // from a polyline to a rest shape
void add_capstan(Registry& registry);              // forward frictional statics: the capstan with bending
void add_bundle(Registry& registry);               // many strands in frictional contact: the factored SOCQP
void add_friction_cone(Registry& registry);        // the cone's threshold tan alpha = mu in the inverse SOCQP
void add_incline_sliding(Registry& registry);      // the same threshold in the forward frictional statics
void add_hanging_fold(Registry& registry);         // the hanging fold: a heavy rod over a ledge (H with friction)

}  // namespace rodvv::harness::inverse_cases
