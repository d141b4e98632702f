// The flexmoor command: run, check and list cases, plot results.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "apps/case/case_reader.hpp"
#include "apps/cli/help_text.hpp"
#include "apps/output/netcdf_file.hpp"
#include "apps/problem/case_error.hpp"
#include "apps/run/draw_figure.hpp"
#include "apps/run/run_case.hpp"
#include "apps/study/run_study.hpp"
#include "apps/study/study_reader.hpp"
#ifdef FLEXMOOR_WITH_MPI
#include "apps/mpi/mpi_study.hpp"
#endif

namespace {

using namespace flexmoor::app;
namespace cli = flexmoor::cli;

// "flexmoor run: CASE is required" and where to look, for every usage error (exit 1).
std::string usageFailure(const CLI::App* app, const CLI::Error& e) {
  const std::vector<CLI::App*> chosen = app->get_subcommands();
  const std::string command = chosen.empty() ? "flexmoor" : "flexmoor " + chosen[0]->get_name();
  std::string what = e.what();
  if (chosen.empty()) {  // CLI11 would say only "A subcommand is required"
    const std::vector<std::string> rest = app->remaining();
    what = "expected a command: run, check, study, cases or plot" +
           (rest.empty() ? std::string() : " (got '" + rest[0] + "')");
  }
  return command + ": " + what + "\nTry '" + command + " --help'.\n";
}

// The case named on the command line, read and checked; nullopt after reporting why not.
std::optional<Case> readNamedCase(const std::string& name) {
  try {
    Case c = readCase(resolveCasePath(name));
    for (const std::string& w : c.warnings) std::cerr << "flexmoor: " << w << "\n";
    return c;
  } catch (const CaseError& e) {
    std::cerr << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
  }
  return std::nullopt;
}

// The study file, read and checked with every member's case; nullopt after reporting why not.
std::optional<Study> readNamedStudy(const std::string& path) {
  try {
    return readStudy(path);
  } catch (const CaseError& e) {
    std::cerr << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
  }
  return std::nullopt;
}

// The path of a case or study named on the command line; the name itself when there is none
// (the reader then says so).
std::string namedPath(const std::string& name) {
  try {
    return resolveCasePath(name);
  } catch (const std::exception&) {
    return name;
  }
}

int check(const std::string& name) {
  if (isStudyFile(namedPath(name))) {
    const std::optional<Study> s = readNamedStudy(namedPath(name));
    if (!s) return kBadInput;
    std::cout << s->file << ": valid study (" << s->members.size() << " members of " << s->base_case
              << ", " << s->collect.size() << " collected)\n";
    return kSuccess;
  }
  const std::optional<Case> c = readNamedCase(name);
  if (!c) return kBadInput;
  std::cout << c->file << ": valid (" << c->model->nodeCount() << " nodes, "
            << c->model->elementCount() << " elements, " << c->model->equationCount()
            << " equations, " << c->steps.size() << " steps)\n";
  return kSuccess;
}

int run(const std::string& name, const RunOptions& options) {
  if (isStudyFile(namedPath(name))) {
    const std::string how = "flexmoor study " + name + " -o DIR";
    std::cerr << "flexmoor: " << namedPath(name) << " is a study, not a case (it has case: and "
              << "collect:); run it with '" << how << "'\n";
    return kBadInput;
  }
  const std::optional<Case> c = readNamedCase(name);
  if (!c) return kBadInput;
  try {
    return runCase(*c, options, std::cout).exit_code;
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kRunFailed;
  }
}

int study(const std::string& file, const StudyOptions& options) {
  try {
#ifdef FLEXMOOR_WITH_MPI
    if (launchedByMpi())
      return runStudyUnderMpi(namedPath(file), options.output_dir, options.workers, std::cout);
#endif
    std::string path;
    try {
      path = resolveCasePath(file);
    } catch (const std::exception& e) {  // no such file: the nearest names
      std::cerr << "flexmoor: " << e.what() << "\n";
      return kBadInput;
    }
    const std::optional<Study> s = readNamedStudy(path);
    if (!s) return kBadInput;
    return runStudy(*s, options, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kRunFailed;
  }
}

// Hands over to apps/plot/flexmoor_plot.py under Debian's interpreter (its matplotlib and
// xarray belong to it); returns only when the interpreter cannot be started.
int plot(const std::string& result, const std::string& png, const std::vector<std::string>& series,
         const std::string& title, const std::vector<std::string>& figure_options) {
  std::vector<std::string> args;
  try {
    args = plotArguments(result, png, series, title, figure_options);
  } catch (const std::exception& e) {  // the script is not found (apps/common/data_dir.hpp)
    std::cerr << "flexmoor plot: " << e.what() << "\n";
    return kRunFailed;
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::cerr << "flexmoor plot: cannot start /usr/bin/python3 (" << std::strerror(errno)
            << "); it needs Debian's python3-matplotlib and python3-xarray\n";
  return kRunFailed;
}

int listNamedCases() {
  try {
    for (const auto& [name, title] : listCases()) std::cout << name << "  " << title << "\n";
  } catch (const std::exception& e) {  // the cases folder is not found (apps/common/data_dir.hpp)
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kRunFailed;
  }
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  turnOffHdf5ExitCleanup();  // before anything starts HDF5 (netcdf_file.hpp)
  CLI::App app(cli::kDescription, "flexmoor");
  app.footer(cli::kOverview);
  app.set_version_flag("--version", std::string("flexmoor ") + FLEXMOOR_VERSION);
  app.require_subcommand(1);
  app.failure_message(usageFailure);

  std::string case_name;
  RunOptions options;  // output_dir is set only by -o (runCase chooses the default)
  bool no_vtk = false, no_figure = false, no_writer_thread = false;
  CLI::App* run_command = app.add_subcommand("run", cli::kRunSummary);
  run_command->footer(cli::kRunDetails);
  run_command->add_option("CASE", case_name, "a case file, or the name of a case under cases/")
      ->required()
      ->type_name("");
  run_command->add_option("-o,--output", options.output_dir, "write the results into DIR")
      ->type_name("DIR");
  run_command->add_flag("--no-vtk", no_vtk, "do not write the .vtk files");
  run_command->add_flag("--no-figure", no_figure, "do not draw the case's figure (DIR/<case>.png)");
  run_command->add_flag("--no-writer-thread", no_writer_thread,
                        "write the netCDF records in the run's own thread (by default a second "
                        "thread writes them while the run goes on, when it streams 1,000 or more)");

  CLI::App* check_command = app.add_subcommand("check", cli::kCheckSummary);
  check_command->footer(cli::kCheckDetails);
  check_command->add_option("CASE", case_name, "a case file, or the name of a case under cases/")
      ->required()
      ->type_name("");

  std::string study_file;
  StudyOptions study_options;
  CLI::App* study_command = app.add_subcommand("study", cli::kStudySummary);
  study_command->footer(cli::kStudyDetails);
  study_command
      ->add_option("STUDY", study_file, "a study file, or the name of a study under cases/")
      ->required()
      ->type_name("");
  study_command->add_option("-o,--output", study_options.output_dir, "write the study into DIR")
      ->required()
      ->type_name("DIR");
  study_command
      ->add_option("-j,--jobs", study_options.workers,
                   "run N members at once (default: the cores; 1 per MPI rank)")
      ->type_name("N")
      ->check(CLI::PositiveNumber);

  CLI::App* cases_command = app.add_subcommand("cases", cli::kCasesSummary);
  cases_command->footer(cli::kCasesDetails);

  std::string result, png, title;
  std::vector<std::string> series;
  CLI::App* plot_command = app.add_subcommand("plot", cli::kPlotSummary);
  plot_command->footer(cli::kPlotDetails);
  plot_command->add_option("RESULT", result, "a run's DIR/<case>.nc or a study's DIR/study.nc")
      ->required()
      ->type_name("");
  plot_command->add_option("-o,--output", png, "the PNG to write")->required()->type_name("PNG");
  plot_command->add_option("--series", series, "VARIABLE@INDEX, one panel each (repeatable)")
      ->type_name("SPEC")
      ->take_all()
      ->allow_extra_args(false);
  plot_command->add_option("--title", title, "the figure's title (default: the file's)")
      ->type_name("TEXT");
  // The other figures' options go to the plot as given; it checks them (help_text.hpp).
  struct FigureOption {
    const char *flag, *type, *help;
    std::string value;
  };
  std::vector<FigureOption> figure_options = {
      {"--spectrum", "SPEC", "the Welch spectrum of one series against the sea's target", ""},
      {"--segment", "SECONDS", "--spectrum: the Welch segment (default: a quarter of the record)",
       ""},
      {"--from", "SECONDS", "--spectrum: leave out the records before this time", ""},
      {"--shapes", "T1,T2,...", "the lines' shapes at the records nearest these times", ""},
      {"--plane", "PLANE", "--shapes: the plane drawn, two of x, y, z (default xz)", ""},
      {"--rao", "NAME", "study: NAME_amplitude against --against (an RAO with --wave-height)", ""},
      {"--extremes", "NAME", "study: NAME_max and NAME_mpm against --against", ""},
      {"--psd", "NAME", "study: the members' response spectra NAME_psd", ""},
      {"--against", "PARAMETER", "--rao, --extremes: the parameter along the horizontal axis", ""},
      {"--group", "PARAMETER", "--rao, --extremes: one colour per value of this parameter", ""},
      {"--wave-height", "H|PARAMETER", "--rao: divide by half this wave height", ""}};
  for (FigureOption& o : figure_options)
    plot_command->add_option(o.flag, o.value, o.help)->type_name(o.type);
  bool mooring = false;
  plot_command->add_flag("--mooring", mooring,
                         "the anchored lines' fairlead tensions and profiles over the seabed");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kSuccess : kUsage;  // help and version exit 0
  }
  options.vtk = !no_vtk;
  options.figure = !no_figure;
  options.background_writer = !no_writer_thread;
  if (check_command->parsed()) return check(case_name);
  if (cases_command->parsed()) return listNamedCases();
  if (study_command->parsed()) return study(study_file, study_options);
  if (plot_command->parsed()) {
    std::vector<std::string> given;
    for (const FigureOption& o : figure_options)
      if (!o.value.empty()) given.insert(given.end(), {o.flag, o.value});
    if (mooring) given.push_back("--mooring");
    return plot(result, png, series, title, given);
  }
  return run(case_name, options);
}
