#include "apps/run/draw_figure.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "apps/common/data_dir.hpp"

extern char** environ;

namespace flexmoor::app {

std::vector<std::string> plotArguments(const std::string& netcdf, const std::string& png,
                                       const std::vector<std::string>& series,
                                       const std::string& title,
                                       const std::vector<std::string>& figure_options) {
  std::vector<std::string> args = {"/usr/bin/python3", plotScript().string(), netcdf, "-o", png};
  for (const std::string& s : series) args.insert(args.end(), {"--series", s});
  args.insert(args.end(), figure_options.begin(), figure_options.end());
  if (!title.empty()) args.insert(args.end(), {"--title", title});
  return args;
}

bool drawFigure(const FigureSpec& figure, const std::string& case_title, const std::string& netcdf,
                const std::string& png, std::ostream& diag) {
  namespace fs = std::filesystem;
  const fs::path target(png);
  const std::string temporary =
      (target.parent_path() / ("." + target.stem().string() + ".tmp.png")).string();
  const bool mooring = figure.kind == FigureSpec::Kind::Mooring;
  std::vector<std::string> args;
  try {
    args = plotArguments(
        netcdf, temporary, figure.series, figure.title.empty() ? case_title : figure.title,
        mooring ? std::vector<std::string>{"--mooring"} : std::vector<std::string>{});
  } catch (const std::runtime_error& e) {  // the script is not found (apps/common/data_dir.hpp)
    diag << "flexmoor: the figure was not drawn: " << e.what() << "; the results are complete\n";
    return false;
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The plot's own line ("wrote ...") is not the run's: its stdout goes nowhere.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) {
    diag << "flexmoor: the figure was not drawn: cannot start /usr/bin/python3 ("
         << std::strerror(started)
         << "); it needs Debian's python3-matplotlib and python3-xarray\n";
    return false;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::error_code ec;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(temporary, ec)) {
    const std::string how = WIFEXITED(status)
                                ? "exited with " + std::to_string(WEXITSTATUS(status))
                                : "was killed by signal " + std::to_string(WTERMSIG(status));
    diag << "flexmoor: the figure " << png << " was not drawn (flexmoor plot " << how
         << "; its message is above); the results are complete\n";
    fs::remove(temporary, ec);
    return false;
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    diag << "flexmoor: the figure was not put in place: " << png << ": " << ec.message() << "\n";
    fs::remove(temporary, ec);
    return false;
  }
  return true;
}

}  // namespace flexmoor::app
