#pragma once
// Frequency analysis about the current (prestressed) state: the lowest modes of
// K_T phi = omega^2 M phi (Chapter IV), by Lanczos iteration in shift-invert mode (Spectra), the
// shifted tangent K_T - sigma M factorised by CHOLMOD. Small systems are solved densely.
#include <limits>
#include <vector>

#include "libstruct/element/element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/solve_log.hpp"

namespace flexmoor::solve {

struct ModalOptions {
  int modes = 10;
  element::MassKind mass = element::MassKind::Consistent;
  // Shift sigma, in omega^2 units; NaN picks a small negative shift so that rigid-body
  // (zero-frequency) modes are found too.
  double shift = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 1e-10;
};

struct ModalResult {
  std::vector<double> omega;              // rad/s, ascending
  std::vector<model::NodalField> shapes;  // mass-normalised mode shapes, 3 x nodes each, each
                                          // with its largest component positive
};

// Throws std::runtime_error when it cannot: a free dof without mass (named with the log's node
// names), a singular shifted tangent, a Lanczos iteration that does not converge.
ModalResult naturalModes(const model::Assembler& assembler, const model::State& state,
                         const ModalOptions& options, const SolveLog& log = {});

}  // namespace flexmoor::solve
