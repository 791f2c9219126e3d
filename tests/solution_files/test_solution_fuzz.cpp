// Mutation fuzzing of the solution-file reader: thousands of corrupted versions of valid files
// (bytes flipped, deleted, duplicated, JSON tokens spliced in, truncations). Each must be read, or
// refused with an InputError; any other exception, a crash or (in the sanitizer build) a memory
// error fails. Deterministic (fixed seed), so a failure reproduces.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::solution_files {
namespace {

const std::vector<std::string> kSeeds = {
    R"({"format": "rodvv-solution", "version": 1, "case": "elastica/mattiasson-2",
        "parameters": {"L": 1.7, "EI": 2.3, "alpha": 2}, "resolution": {"N": 3}, "solver": "x",
        "planar_rod": {"length": 1.7, "axial_stiffness": 1e5, "shear_stiffness": 1e5, "iterations": 3,
          "nodes": {"s": [0, 0.5, 1.2, 1.7], "x": [0, 0.5, 1.1, 1.5], "y": [0, -0.1, -0.3, -0.6],
                    "theta": [0, -0.2, -0.5, -0.6], "kappa": [-0.4, -0.3, -0.2, 0],
                    "force_x": [0, 0, 0, 0], "force_y": [-1, -1, -1, -1], "bending_stiffness": [2.3, 2.3, 2.3, 2.3]}}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "c", "resolution": {"N": 2},
        "planar_rod": {"nodes": {"s": [0, 0.5, 1], "x": [0, 0.5, 1], "y": [0, 0, 0]}}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "p", "resolution": {"omega_dt": 0.1},
        "trajectory": {"steps": 2, "samples": {"t": [0, 0.1, 0.2], "theta": [1, 0.9, 0.7], "theta_dot": [0, -1, -2]}}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "rod3d/skew-vibration", "resolution": {"N": 2},
        "rod_trajectory": {"steps": 4, "samples": {"t": [0, 0, 0, 0.1, 0.1, 0.1, 0.2, 0.2, 0.2],
          "s": [0, 0.5, 1, 0, 0.5, 1, 0, 0.5, 1], "position_x": [0, 0.5, 1, 0, 0.5, 1, 0, 0.5, 1],
          "position_y": [0, 0.01, 0.03, 0, 0, 0, 0, -0.01, -0.03], "position_z": [0, 0, 0.01, 0, 0, 0, 0, 0, -0.01]}}})",
};

const std::vector<std::string> kTokens = {"null", "true", "-", "1e999", "-0", "[]", "{}", "\"", ",", ":", "[",
                                          "]", "{", "}", "0", "1e-320", "\"s\"", "NaN", "\\u0000", "1.5"};

std::string mutate(std::string text, std::mt19937_64& random) {
  const int edits = 1 + int(random() % 4);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = random() % text.size();
    switch (random() % 5) {
      case 0: text[at] = char(random() % 256); break;
      case 1: text.erase(at, 1 + random() % 8); break;
      case 2: text.insert(at, text.substr(random() % text.size(), 1 + random() % 16)); break;
      case 3: text.insert(at, kTokens[random() % kTokens.size()]); break;
      default: text.resize(at); break;
    }
  }
  return text;
}

TEST(SolutionFileFuzz, CorruptedFilesAreReadOrRefusedWithInputError) {
  std::mt19937_64 random(20261126);
  std::size_t refused = 0, read = 0;
  for (int round = 0; round < 6000; ++round) {
    const std::string text = mutate(kSeeds[round % kSeeds.size()], random);
    try {
      parse_solution(text, "fuzz.json", ".");
      ++read;
    } catch (const InputError& error) {
      ++refused;
      EXPECT_NE(std::string(error.what()).find("fuzz.json"), std::string::npos) << error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what() << "\nfor: " << text;
    }
  }
  // Both outcomes occur: the mutations reach past the JSON syntax into the format's checks.
  EXPECT_GT(refused, 1000u);
  EXPECT_GT(read, 10u);
}

TEST(SolutionFileFuzz, DeepNestingIsRefusedNotAStackOverflow) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_THROW(parse_solution(deep, "deep.json", "."), InputError);
}

}  // namespace
}  // namespace rodvv::solution_files
