// The sanitizers' teeth: defects that the asan preset must report, one per argument. CTest runs each
// and passes only on the sanitizer's report (tests/sanitizer/CMakeLists.txt), so a preset whose
// instrumentation went missing, or lost a check it relies on, turns red.
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

// Read the index and the value at run time so that the compiler cannot fold or drop the defect.
int heap_read_past_the_end(int index) {
  const std::vector<int> values(4, 1);
  return values.data()[index];  // index 4: one past the allocation (data(), not operator[]: no assertion first)
}

int signed_overflow(int start) { return start + 1; }  // start = INT_MAX

int use_after_free(int index) {
  int* values = new int[4]{1, 2, 3, 4};
  delete[] values;
  return values[index];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: sanitizer_canary heap|overflow|use-after-free N\n");
    return 2;
  }
  const int n = std::stoi(argv[2]);
  int result = 0;
  if (std::strcmp(argv[1], "heap") == 0) result = heap_read_past_the_end(n);
  else if (std::strcmp(argv[1], "overflow") == 0) result = signed_overflow(std::numeric_limits<int>::max() - n);
  else if (std::strcmp(argv[1], "use-after-free") == 0) result = use_after_free(n);
  else return 2;
  std::printf("no report: %d\n", result);
  return 0;
}
