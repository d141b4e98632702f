#include "apps/run/run_case.hpp"

#include <filesystem>
#include <iomanip>
#include <ostream>

#include "apps/output/netcdf_writer.hpp"
#include "apps/output/summary_json.hpp"
#include "apps/output/summary_quantities.hpp"
#include "apps/output/vtk_writer.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"

namespace flexmoor::app {
namespace {

// Support reactions: F - P at the constrained dofs, zero elsewhere.
model::NodalField reactions(const model::Model& m, const model::Assembler& a,
                            const model::State& s) {
  Eigen::VectorXd F, P;
  a.internalForce(s, F, nullptr);
  a.externalLoad(s, P);
  model::NodalField r = model::NodalField::Zero(3, m.nodeCount());
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (m.isConstrained(n, k)) r(k, n) = F(3 * n + k) - P(3 * n + k);
  return r;
}

ResultFrame makeFrame(const Case& c, const model::Assembler& a, int step, std::string name,
                      const model::State& s) {
  ResultFrame f;
  f.step_index = step;
  f.step_name = std::move(name);
  f.state = &s;
  f.elements = a.elementResults(s);
  f.reactions = reactions(*c.model, a, s);
  return f;
}

void runStep(const StepSpec& step, const model::Assembler& a, model::State& s,
             const solve::SolveLog& slog, std::ostream& log) {
  if (step.kind == StepSpec::Kind::Relax) {
    const solve::RelaxationReport r = solve::relax(a, s, step.relax, slog);
    log << "  relaxed in " << r.steps << " steps (" << r.iterations
        << " Newton iterations), change " << r.change_ratio << ", residual " << r.residual_norm
        << "\n";
  } else {
    const solve::StaticReport r = solve::solveStatic(a, s, step.statics, slog);
    int iterations = 0;
    for (const auto& inc : r.increments) iterations += inc.iterations;
    log << "  equilibrium at load factor " << s.load_factor << " in " << r.increments.size()
        << " increments (" << iterations << " iterations)\n";
  }
}

std::vector<std::pair<std::string, double>> evaluate(const Case& c,
                                                      const std::vector<ResultFrame>& frames,
                                                      std::vector<std::pair<std::string, std::string>>& units) {
  std::vector<std::pair<std::string, double>> values;
  for (const SummarySpec& spec : c.summary) {
    const int step = spec.step < 0 ? static_cast<int>(c.steps.size()) - 1 : spec.step;
    if (step >= static_cast<int>(frames.size())) continue;  // that step never finished
    values.emplace_back(spec.name, evaluateSummary(spec, *c.model, frames[step]));
    units.emplace_back(spec.name, spec.unit);
  }
  return values;
}

}  // namespace

RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log) {
  namespace fs = std::filesystem;
  fs::create_directories(options.output_dir);
  RunOutcome out;
  out.netcdf_path = (fs::path(options.output_dir) / (c.name + ".nc")).string();
  out.summary_path = (fs::path(options.output_dir) / "summary.json").string();

  const model::Model& m = *c.model;
  model::Assembler assembler(m);
  NetcdfWriter writer(out.netcdf_path, m, c);
  log << "flexmoor: case " << c.name << " (" << c.file << ")\n  " << m.nodeCount() << " nodes, "
      << m.elementCount() << " elements, " << m.equationCount() << " equations, "
      << c.steps.size() << " steps\n";

  std::vector<model::State> states;
  states.reserve(c.steps.size() + 1);
  std::vector<ResultFrame> frames;
  model::State state = m.initialState();
  solve::SolveLog slog;
  slog.message = [&log](const std::string& s) { log << "  " << s << std::endl; };

  for (size_t i = 0; i < c.steps.size(); ++i) {
    const StepSpec& step = c.steps[i];
    log << "step " << i + 1 << "/" << c.steps.size() << ": " << step.name << std::endl;
    try {
      runStep(step, assembler, state, slog, log);
    } catch (const solve::ConvergenceError& e) {
      log << "flexmoor: step " << i + 1 << " (" << step.name << ", " << step.where.file << ":"
          << step.where.line << ") did not converge: " << e.what() << std::endl;
      states.push_back(state);
      writer.write(makeFrame(c, assembler, static_cast<int>(i), step.name + " (last converged)",
                             states.back()));
      log << "  last converged state written to " << out.netcdf_path << "\n";
      out.exit_code = kNotConverged;
      break;
    }
    states.push_back(state);
    frames.push_back(makeFrame(c, assembler, static_cast<int>(i), step.name, states.back()));
    writer.write(frames.back());
    if (options.vtk) {
      const fs::path vtk = fs::path(options.output_dir) / (c.name + "-" + std::to_string(i + 1) + ".vtk");
      writeVtk(vtk.string(), m, frames.back());
    }
  }

  std::vector<std::pair<std::string, std::string>> units;
  out.summary = evaluate(c, frames, units);
  writeSummaryJson(out.summary_path, c.name, out.summary, units);
  log << "summary (" << unitNames(c.units).length << ", " << unitNames(c.units).force << "):\n";
  for (size_t k = 0; k < out.summary.size(); ++k)
    log << "  " << std::left << std::setw(24) << out.summary[k].first << std::setprecision(8)
        << out.summary[k].second << " " << units[k].second << "\n";
  log << "results: " << out.netcdf_path << "\n         " << out.summary_path << "\n";
  return out;
}

}  // namespace flexmoor::app
