#pragma once
// The data that poses a case's problem to another solver, where the case's own text cannot: the
// manufactured solutions' load fields, which come out of the manufacture (references/manufactured_*)
// and are not a formula a user could type. `rodvv problem CASE --stations M --out FILE` writes it
// (README, "Checking your own solver"); the user's solver applies it and its solution files go to
// `rodvv check`.
//
// Scalars (end loads, clamp pose, stiffness, field coefficients) by name, and per-station fields as
// named columns, the first one "s", at the stations the caller asks for. Units: the case's parameters'.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rodvv/harness/parameters.hpp"

namespace rodvv::harness {

struct ProblemData {
  std::string description;                             // what the values and columns are and how to apply them
  std::vector<std::pair<std::string, double>> values;  // scalars, in order
  std::vector<std::string> columns;                    // per-station fields; columns[0] = "s"
  std::vector<std::vector<double>> rows;               // rows[i][j]: column j at station i
};

// The problem's data at intervals + 1 uniform stations s_i = L i / intervals (intervals >= 1).
using ProblemDataAt = std::function<ProblemData(const Parameters& parameters, std::size_t intervals)>;

// The uniform stations s_i = length i / intervals, i = 0 .. intervals (the last exactly length).
std::vector<double> uniform_stations(double length, std::size_t intervals);

}  // namespace rodvv::harness
