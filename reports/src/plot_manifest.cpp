#include "rodvv/reports/plot_manifest.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

#include "rodvv/common/errors.hpp"

namespace rodvv::reports {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& field,
                       const std::string& problem) {
  throw InputError("plot manifest", path.string() + ": field '" + field + "': " + problem);
}

std::map<std::string, std::vector<PlotFile>> read_section(const json& document,
                                                          const std::filesystem::path& path,
                                                          const std::string& key) {
  std::map<std::string, std::vector<PlotFile>> out;
  const auto section = document.find(key);
  if (section == document.end()) return out;  // a manifest without groups is fine
  if (!section->is_object()) fail(path, key, "expected an object");
  for (const auto& [name, list] : section->items()) {
    const std::string field = key + "['" + name + "']";
    if (!list.is_array()) fail(path, field, "expected an array");
    auto& files = out[name];
    for (std::size_t i = 0; i < list.size(); ++i) {
      const json& entry = list[i];
      const std::string entry_field = field + "[" + std::to_string(i) + "]";
      if (!entry.is_object()) fail(path, entry_field, "expected an object");
      const auto file = entry.find("file");
      if (file == entry.end() || !file->is_string())
        fail(path, entry_field + ".file", "expected a string");
      const auto caption = entry.find("caption");
      PlotFile plot;
      plot.file = file->get<std::string>();
      if (caption != entry.end() && caption->is_string()) plot.caption = caption->get<std::string>();
      files.push_back(std::move(plot));
    }
  }
  return out;
}

}  // namespace

PlotManifest read_plot_manifest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("plot manifest", path.string() + ": cannot open");
  json document;
  try {
    document = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError("plot manifest", path.string() + ": not valid JSON: " + e.what());
  }
  if (!document.is_object()) fail(path, "", "expected a JSON object");
  PlotManifest manifest;
  manifest.cases = read_section(document, path, "cases");
  manifest.groups = read_section(document, path, "groups");
  return manifest;
}

}  // namespace rodvv::reports
