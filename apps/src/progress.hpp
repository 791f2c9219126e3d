#pragma once
// Progress lines on stderr (results go to stdout or files): one line per finished case, and with
// --verbose one per level.
#include <cstddef>

#include "rodvv/harness/sweep.hpp"

namespace rodvv::apps {

class ProgressReporter {
 public:
  ProgressReporter(std::size_t case_count, bool verbose) : case_count_(case_count), verbose_(verbose) {}
  harness::ProgressCallback level_callback() const;
  void case_finished(const harness::SweepResult& result);

 private:
  std::size_t case_count_;
  std::size_t cases_done_ = 0;
  bool verbose_;
};

}  // namespace rodvv::apps
