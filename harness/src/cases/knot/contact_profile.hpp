#pragma once
// The self-contact force along a knotted rod, for the report beside H(s) (issue 12: H through the braid
// and the ply with the contact forces).
#include <vector>

#include "rodvv/harness/sweep_result.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace rodvv::harness::knot_cases {

// "contact force p(s)": the magnitude of the contact force per unit length at each vertex, each pair's
// force split between the end vertices of its two segments by the closest-point parameters (the
// barrier's own lumping, self_contact.hpp) and divided by the rest edge length; s = vertex_arclength.
Series contact_force_series(const solvers::rod3d::RodModel& model,
                            const std::vector<solvers::rod3d::ContactPair>& contacts);

// The same for the Super-Helix's line contact (superhelix/self_contact.hpp): at each Gauss point in
// contact, its line force density k (2h - d)^2 summed over its feet; s = the point's arclength.
Series contact_force_series(double element_length, const solvers::superhelix::SelfContact& contact,
                            const std::vector<solvers::superhelix::ArcContact>& contacts);

// "contact point forces f": hard self-contact's point forces (superhelix/hard_self_contact.hpp), each
// loaded pair's multiplier at the arclengths of both its closest points.
Series point_contact_force_series(double element_length, const std::vector<solvers::superhelix::ArcContact>& contacts);

}  // namespace rodvv::harness::knot_cases
