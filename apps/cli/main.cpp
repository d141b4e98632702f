// The flexmoor command: run, check and list cases.
#include <cstring>
#include <iostream>
#include <string>

#include "apps/case/case_reader.hpp"
#include "apps/case/diagnostics.hpp"
#include "apps/run/run_case.hpp"

namespace {

constexpr const char* kHelp =
    R"(flexmoor - nonlinear finite-element analysis of cables, mooring lines and membranes

Usage:
  flexmoor run CASE [-o DIR] [--no-vtk]   run a case; results go to DIR (default: results/)
  flexmoor check CASE                    validate a case file without running it
  flexmoor cases                         list the named cases shipped under cases/
  flexmoor --help | --version

CASE is a path to a YAML case file or the name of a case under cases/ (for example
ex1-suspended-cable-8xL2). A case states its unit system (US: ft, slug, s, lbf; SI: m, kg, s, N);
any value may carry its own unit ("0.163 in", "500000 psi") and is converted once on reading.

A run executes the case's steps in order, each from the state the previous one left:
  relax   viscous relaxation (Appendix C) from an unstable, unstressed start to equilibrium
  static  load increments with Newton-Raphson, modified Newton or BFGS (Eq. 5.1 convergence),
          or arc-length control through limit points (control: arc_length)
  modes   the lowest natural frequencies and mode shapes about the current, prestressed state
  dynamic Newmark (Eq. 4.55-4.63) or HHT-alpha time steps with Newton iterations, by a
          schedule of {dt, steps}; failed steps are halved and retried; progress is logged
and writes
  DIR/<case>.nc         netCDF-4, CF-style names with units: coordinates, displacements,
                        velocities, reactions, tensions, membrane resultants and mode shapes,
                        one record per step or per output time (flushed as it goes)
  DIR/<case>-<n>.vtk    the deformed shape (and mode shapes) after step n, for ParaView
  DIR/summary.json      the case's declared summary quantities with their units

Exit codes: 0 done; 1 usage error; 2 the case file is invalid (every problem is listed as
FILE:LINE: what is wrong); 3 a step did not converge (the last converged state is written);
4 the run failed otherwise (an output could not be written, a value was not finite).

Examples:
  flexmoor cases
  flexmoor check cases/seed/ex1-suspended-cable-4xL3.yaml
  flexmoor run ex1-suspended-cable-8xL2 -o results

The case-file format (materials, sections, lines, surfaces, supports, loads, histories, steps,
summary) is described in README.md, and every shipped case under cases/ is a worked example.
)";

int usage(const std::string& what) {
  std::cerr << "flexmoor: " << what << "\nTry 'flexmoor --help'.\n";
  return flexmoor::app::kUsage;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace flexmoor::app;
  if (argc < 2) return usage("missing command");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kHelp;
    return kSuccess;
  }
  if (command == "--version") {
    std::cout << "flexmoor " << FLEXMOOR_VERSION << "\n";
    return kSuccess;
  }
  if (command == "cases") {
    for (const auto& [name, title] : listCases()) std::cout << name << "  " << title << "\n";
    return kSuccess;
  }
  if (command != "run" && command != "check") return usage("unknown command '" + command + "'");
  if (argc < 3) return usage(command + " needs a CASE");

  RunOptions options;
  for (int i = 3; i < argc; ++i) {
    if ((!std::strcmp(argv[i], "-o") || !std::strcmp(argv[i], "--output")) && i + 1 < argc)
      options.output_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--no-vtk"))
      options.vtk = false;
    else
      return usage("unexpected argument '" + std::string(argv[i]) + "'");
  }

  Case c;
  try {
    c = readCase(resolveCasePath(argv[2]));
  } catch (const CaseError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kBadInput;
  }
  if (command == "check") {
    std::cout << c.file << ": valid (" << c.model->nodeCount() << " nodes, "
              << c.model->elementCount() << " elements, " << c.model->equationCount()
              << " equations, " << c.steps.size() << " steps)\n";
    return kSuccess;
  }
  try {
    return runCase(c, options, std::cout).exit_code;
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kRunFailed;
  }
}
