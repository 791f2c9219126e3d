#pragma once
// Default element counts and gates of the elastica cases, measured first with
// `rodvv sweep CASE --levels ...` and fixed here (elastica_levels.cpp).
#include <string>
#include <string_view>
#include <vector>

#include "rodvv/harness/gate.hpp"

namespace rodvv::harness {

struct ElasticaLevelPlan {
  std::vector<double> levels;           // N, coarse -> fine
  std::vector<double> extended_levels;  // `--extended`
  std::vector<GateSpec> gates;
};

// motion: "pinned-pinned-60", "pinned-displacement", "mattiasson-1", "roll-up", "tapered", ...;
// scheme: "polygon" or "arcs".
ElasticaLevelPlan elastica_level_plan(std::string_view motion, std::string_view scheme);

}  // namespace rodvv::harness
