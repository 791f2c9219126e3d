#pragma once
// Where and how a set of results was produced: enough to tell two reports apart and to rebuild
// the binary that made one (commit, compiler, flags) and to judge its timings (CPU, cores).
#include <string>

namespace rodvv::reports {

struct Provenance {
  std::string rodvv_version;
  std::string git_commit;        // commit hash, "-dirty" if the tree had changes; or "unknown"
  std::string compiler_id;       // "GNU", "Clang"
  std::string compiler_version;
  std::string build_type;        // "Release", "RelWithDebInfo"
  std::string compile_flags;
  std::string cpu_model;         // /proc/cpuinfo "model name", or "unknown"
  unsigned host_cores = 0;       // std::thread::hardware_concurrency(); 0 if unknown
  std::string date_utc;          // ISO 8601, "2024-05-01T12:34:56Z"
};

// Build-time facts (build_info()) plus the host and the current time.
Provenance collect_provenance();

}  // namespace rodvv::reports
