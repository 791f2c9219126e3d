#include "rodvv/reports/provenance.hpp"

#include <ctime>
#include <fstream>
#include <string_view>
#include <thread>

#include "rodvv/reports/build_info.hpp"

namespace rodvv::reports {

namespace {

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(first, last - first + 1));
}

// x86 and most Linux kernels list "model name"; some ARM kernels have no such line.
std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string model = trim(std::string_view(line).substr(colon + 1));
    if (!model.empty()) return model;
  }
  return "unknown";
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  if (gmtime_r(&now, &utc) == nullptr) return "unknown";
  char buffer[32];
  const std::size_t n = std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return n == 0 ? std::string("unknown") : std::string(buffer, n);
}

}  // namespace

Provenance collect_provenance() {
  const BuildInfo build = build_info();
  Provenance p;
  p.rodvv_version = std::string(build.version);
  p.git_commit = std::string(build.git_commit);
  p.compiler_id = std::string(build.compiler_id);
  p.compiler_version = std::string(build.compiler_version);
  p.build_type = std::string(build.build_type);
  p.compile_flags = std::string(build.compile_flags);
  p.cpu_model = cpu_model();
  p.host_cores = std::thread::hardware_concurrency();
  p.date_utc = utc_now_iso8601();
  return p;
}

}  // namespace rodvv::reports
