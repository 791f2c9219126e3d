// libFuzzer target: the CSV tables of a solution file (nodes_csv, vertices_csv, stations_csv,
// samples_csv), through the public reader parse_solution, so that what follows the table (the
// derivation of theta and kappa from positions, the spatial frames, the trajectory checks) sees
// the fuzzed numbers too. The first byte chooses the table; the rest is the CSV file's content,
// written to a file in a per-process temporary directory (the reader takes CSV only from files).
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_contract.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace {

// Minimal valid headers, one per table kind; only the CSV varies.
constexpr std::array<const char*, 4> kHeaders = {
    R"({"format": "rodvv-solution", "version": 1, "case": "elastica/mattiasson-2", "resolution": {"N": 4},
        "planar_rod": {"nodes_csv": "table.csv"}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "rod3d/mattiasson-2", "resolution": {"N": 4},
        "spatial_rod": {"vertices_csv": "table.csv"}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "rod3d/mattiasson-2", "resolution": {"N": 4},
        "spatial_rod": {"vertices": {"position_x": [0, 0.5, 1, 1.5, 2], "position_y": [0, 0, 0, 0, 0],
                                     "position_z": [0, 0, 0, 0, 0]}, "stations_csv": "table.csv"}})",
    R"({"format": "rodvv-solution", "version": 1, "case": "pendulum/libration-30/rk4",
        "resolution": {"omega_dt": 0.1}, "trajectory": {"samples_csv": "table.csv"}})",
};

const std::filesystem::path& scratch_directory() {
  static const std::filesystem::path directory = [] {
    auto path = std::filesystem::temp_directory_path() / ("rodvv-fuzz-csv-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return directory;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char* header = kHeaders[data[0] % kHeaders.size()];
  {
    std::ofstream csv(scratch_directory() / "table.csv", std::ios::binary | std::ios::trunc);
    csv.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  rodvv::fuzz::expect_read_or_input_error("fuzz_solution_csv", [&] {
    rodvv::solution_files::parse_solution(header, "fuzz.json", scratch_directory());
  });
  return 0;
}
