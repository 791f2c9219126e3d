#pragma once
// Writes a whole report directory from one ValidationReport:
//   results.json  results.csv  report.md  junit.xml  plots/*.png  plots/manifest.json
//   plots/plot.log  index.html
// Plots come from plot_results.py run under python; if that is impossible (no interpreter, no
// matplotlib, the script fails) the tables are still written, index.html says
// "plots unavailable: <reason>" and WrittenReport says why. Nothing here aborts over plots.
#include <filesystem>
#include <string>
#include <vector>

#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

struct WriteOptions {
  // The plot script. Empty: $RODVV_PLOT_SCRIPT, else the source tree's reports/plot_results.py
  // (compile-time RODVV_PLOT_SCRIPT), else <exe dir>/../share/rodvv/plot_results.py.
  std::filesystem::path plot_script;
  // The interpreter. Empty: $RODVV_PYTHON, else /usr/bin/python3 (Debian's, with matplotlib).
  std::string python;
  bool make_plots = true;
};

struct WrittenReport {
  std::vector<std::filesystem::path> files;  // every file written, index.html last
  bool plots_ok = false;
  std::string plots_message;  // "N plots" or the reason plots are unavailable
};

// Creates out_dir if needed. Throws rodvv::InputError if out_dir or a file in it cannot be
// written.
WrittenReport write_report_directory(const ValidationReport& report,
                                     const std::filesystem::path& out_dir,
                                     const WriteOptions& options = {});

}  // namespace rodvv::reports
