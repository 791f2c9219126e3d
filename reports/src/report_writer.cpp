#include "rodvv/reports/report_writer.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <system_error>

#include "rodvv/common/errors.hpp"
#include "rodvv/reports/csv.hpp"
#include "rodvv/reports/html.hpp"
#include "rodvv/reports/json_io.hpp"
#include "rodvv/reports/junit.hpp"
#include "rodvv/reports/markdown.hpp"
#include "rodvv/reports/plot_manifest.hpp"

extern char** environ;

namespace rodvv::reports {

namespace fs = std::filesystem;

namespace {

constexpr const char* kDefaultPython = "/usr/bin/python3";

void write_text(const fs::path& path, const std::string& text, WrittenReport& written) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError("output file", path.string() + ": cannot write: " + std::strerror(errno));
  out << text;
  out.flush();
  if (!out) throw InputError("output file", path.string() + ": write failed");
  written.files.push_back(path);
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}

// The source-tree script while it exists (developer builds), else the installed copy next to
// the executable's prefix (<prefix>/bin/rodvv -> <prefix>/share/rodvv/plot_results.py).
fs::path default_plot_script() {
  if (const char* env = std::getenv("RODVV_PLOT_SCRIPT"); env && *env) return env;
  std::error_code ec;
  const fs::path source = RODVV_PLOT_SCRIPT;
  if (fs::exists(source, ec)) return source;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / RODVV_INSTALL_DATADIR / "rodvv" /
                               "plot_results.py";
    if (fs::exists(installed, ec)) return installed;
  }
  return source;  // missing: the error message then names the expected place
}

// The last non-empty line of the script's log: its own message on a handled failure
// ("matplotlib is not available ...") or the exception line of a traceback.
std::string last_line(const fs::path& log) {
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

struct ScriptRun {
  bool ok = false;
  std::string message;
};

// posix_spawn, not std::system: no shell, so no quoting of paths with spaces or quotes.
// stdout and stderr both go to the log; stdin is /dev/null.
ScriptRun run_plot_script(const std::string& python, const fs::path& script,
                          const fs::path& results, const fs::path& plots_dir,
                          const fs::path& log) {
  std::error_code ec;
  if (!fs::exists(script, ec)) return {false, "plot script not found: " + script.string()};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // Our stderr, as the child's descriptor 3 (before 1 and 2 go to the log): the script's progress
  // bar reaches the user while its messages and tracebacks stay in the log.
  constexpr int kProgressFd = 3;
  posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, kProgressFd);
  const std::string log_path = log.string();
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);

  std::string arg0 = python, arg1 = script.string(), arg2 = results.string(),
              arg3 = plots_dir.string(), arg4 = "--progress-fd=" + std::to_string(kProgressFd);
  char* argv[] = {arg0.data(), arg1.data(), arg2.data(), arg3.data(), arg4.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0)
    return {false, "cannot run " + python + ": " + std::strerror(spawn_error)};

  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return {false, std::string("waiting for the plot script: ") + std::strerror(errno)};
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {true, ""};
  std::string why = last_line(log);
  if (WIFSIGNALED(status))
    why = "plot script killed by signal " + std::to_string(WTERMSIG(status));
  else if (why.empty())
    why = "plot script exited with status " + std::to_string(WEXITSTATUS(status));
  return {false, why + " (see " + log.string() + ")"};
}

}  // namespace

WrittenReport write_report_directory(const ValidationReport& report, const fs::path& out_dir,
                                     const WriteOptions& options) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir))
    throw InputError("output directory",
                     out_dir.string() + ": cannot create: " + (ec ? ec.message() : "not a directory"));

  WrittenReport written;
  const fs::path results = out_dir / "results.json";
  write_report_file(results, report);
  written.files.push_back(results);
  write_text(out_dir / "results.csv", render_csv(report), written);
  write_text(out_dir / "report.md", render_markdown(report), written);
  write_text(out_dir / "junit.xml", render_junit(report), written);

  PlotManifest manifest;
  if (!options.make_plots) {
    manifest.unavailable_reason = "plots disabled";
  } else {
    const fs::path plots_dir = out_dir / "plots";
    fs::create_directories(plots_dir, ec);
    const fs::path manifest_path = plots_dir / "manifest.json";
    const fs::path log = plots_dir / "plot.log";
    fs::remove(manifest_path, ec);  // never show a stale manifest from an earlier run
    const std::string python =
        options.python.empty() ? env_or("RODVV_PYTHON", kDefaultPython) : options.python;
    const fs::path script = options.plot_script.empty() ? default_plot_script() : options.plot_script;
    ScriptRun run;
    if (!fs::is_directory(plots_dir, ec))
      run = {false, "cannot create " + plots_dir.string()};
    else
      run = run_plot_script(python, script, results, plots_dir, log);
    if (run.ok) {
      try {
        manifest = read_plot_manifest(manifest_path);
        written.files.push_back(manifest_path);
        for (const auto& [name, files] : manifest.cases)
          for (const auto& f : files) written.files.push_back(out_dir / f.file);
        for (const auto& [name, files] : manifest.groups)
          for (const auto& f : files) written.files.push_back(out_dir / f.file);
      } catch (const InputError& e) {
        run = {false, e.what()};
      }
    }
    if (fs::exists(log, ec)) written.files.push_back(log);
    if (!run.ok) manifest = PlotManifest{{}, {}, run.message};
  }

  written.plots_ok = manifest.unavailable_reason.empty();
  if (written.plots_ok) {
    std::size_t count = 0;
    for (const auto& [name, files] : manifest.cases) count += files.size();
    for (const auto& [name, files] : manifest.groups) count += files.size();
    written.plots_message = std::to_string(count) + " plots";
  } else {
    written.plots_message = "plots unavailable: " + manifest.unavailable_reason;
  }
  write_text(out_dir / "index.html", render_html(report, manifest), written);
  return written;
}

}  // namespace rodvv::reports
