#pragma once
// plots/manifest.json, written by plot_results.py: which images belong to which case and group.
//   {"cases": {case_name: [{"file": "plots/x.png", "caption": "..."}]}, "groups": {group: [...]}}
// File paths are relative to the report directory (where index.html is).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rodvv::reports {

struct PlotFile {
  std::string file;
  std::string caption;
};

struct PlotManifest {
  std::map<std::string, std::vector<PlotFile>> cases;   // by CaseInfo.name
  std::map<std::string, std::vector<PlotFile>> groups;  // by CaseInfo.group
  // Non-empty when no plots could be made (no python, no matplotlib, the script failed);
  // the HTML then shows "plots unavailable: <reason>".
  std::string unavailable_reason;
};

// Throws rodvv::InputError (parameter "plot manifest") naming the file and field.
PlotManifest read_plot_manifest(const std::filesystem::path& path);

}  // namespace rodvv::reports
