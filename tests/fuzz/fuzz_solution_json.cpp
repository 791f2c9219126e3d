// libFuzzer target: a solution file's JSON text (`rodvv check --solution F`), through the public
// reader parse_solution. Inline node, vertex, station and sample tables; *_csv references resolve
// against a directory holding no files, so they are refused cleanly (fuzz_solution_csv covers CSV).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_contract.hpp"
#include "rodvv/solution_files/solution_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rodvv::fuzz::expect_read_or_input_error("fuzz_solution_json", [&] {
    rodvv::solution_files::parse_solution(text, "fuzz.json", "/nonexistent-rodvv-fuzz-directory");
  });
  return 0;
}
