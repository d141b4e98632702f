#include "libstruct/solve/modal.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "libstruct/solve/diagnosis.hpp"
#include "libstruct/solve/linear_solver.hpp"

namespace flexmoor::solve {
namespace {

// y = (K - sigma M)^-1 x with the factorisation of LinearSolver (CHOLMOD, LU as fallback).
class ShiftInvertOperator {
 public:
  using Scalar = double;
  ShiftInvertOperator(const model::SparseMatrix& K, const model::SparseMatrix& M) : K_(K), M_(M) {}
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  void set_shift(double sigma) {
    if (!solver_.factorize(model::SparseMatrix(K_ - sigma * M_)))
      throw std::runtime_error("frequency analysis: K - sigma M is singular at the shift");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd>(y_out, rows()) = solver_.solve(x);
  }

 private:
  const model::SparseMatrix& K_;
  const model::SparseMatrix& M_;
  LinearSolver solver_;
};

constexpr int kDenseLimit = 200;  // below this many equations a dense solve is faster

void denseModes(const model::SparseMatrix& K, const model::SparseMatrix& M, int modes,
                Eigen::VectorXd& eigenvalues, Eigen::MatrixXd& vectors) {
  const Eigen::MatrixXd K_dense = K, M_dense = M;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K_dense, M_dense);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("frequency analysis: the mass matrix is not positive definite");
  eigenvalues = solver.eigenvalues().head(modes);
  vectors = solver.eigenvectors().leftCols(modes);
}

void sparseModes(const model::SparseMatrix& K, const model::SparseMatrix& M, int modes,
                 double sigma, double tolerance, Eigen::VectorXd& eigenvalues,
                 Eigen::MatrixXd& vectors) {
  ShiftInvertOperator op(K, M);
  Spectra::SparseSymMatProd<double> mass(M);
  const int n = static_cast<int>(K.rows());
  const int ncv = std::min(n, std::max(2 * modes + 1, modes + 20));
  Spectra::SymGEigsShiftSolver<ShiftInvertOperator, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      eigs(op, mass, modes, ncv, sigma);
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestMagn, 1000, tolerance, Spectra::SortRule::SmallestAlge);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("frequency analysis: Lanczos iteration did not converge");
  eigenvalues = eigs.eigenvalues();
  vectors = eigs.eigenvectors();
}

// A free dof whose mass is not positive makes M singular or indefinite: name the first.
void requireMass(const model::Model& m, const model::SparseMatrix& M, const SolveLog& log) {
  const Eigen::VectorXd diagonal = M.diagonal();
  for (int n = 0; n < m.nodeCount(); ++n)
    for (int k = 0; k < 3; ++k)
      if (const int eq = m.equation(n, k); eq >= 0 && !(diagonal(eq) > 0.0))
        throw std::runtime_error(
            "frequency analysis: the mass matrix is not positive definite: " + dofName(log, n, k) +
            " has no mass (every element on it has zero density, or none carries it)");
}

}  // namespace

ModalResult naturalModes(const model::Assembler& assembler, const model::State& state,
                         const ModalOptions& options, const SolveLog& log) {
  model::SparseMatrix K, M;
  Eigen::VectorXd F;
  assembler.internalForce(state, F, &K);
  assembler.mass(state, options.mass, M);
  requireMass(assembler.model(), M, log);
  const int n = assembler.equationCount();
  const int modes = std::min(options.modes, n);
  if (modes < 1) throw std::invalid_argument("frequency analysis needs at least one mode");

  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd vectors;
  if (n <= kDenseLimit || modes >= n / 2) {
    denseModes(K, M, modes, eigenvalues, vectors);
  } else {
    double sigma = options.shift;
    if (std::isnan(sigma)) sigma = -1e-6 * K.diagonal().cwiseAbs().sum() / M.diagonal().sum();
    sparseModes(K, M, modes, sigma, options.tolerance, eigenvalues, vectors);
  }

  ModalResult result;
  for (int k = 0; k < modes; ++k) {
    Eigen::VectorXd phi = vectors.col(k) / std::sqrt(vectors.col(k).dot(M * vectors.col(k)));
    // An eigenvector's sign is arbitrary, and round-off flips it from one build to another: the
    // shape is given with its largest component positive, so runs compare.
    Eigen::Index largest = 0;
    phi.cwiseAbs().maxCoeff(&largest);
    if (phi(largest) < 0.0) phi = -phi;
    result.omega.push_back(std::sqrt(std::max(0.0, eigenvalues(k))));
    model::NodalField shape = model::NodalField::Zero(3, state.displacement.cols());
    assembler.addFree(phi, shape);
    result.shapes.push_back(std::move(shape));
  }
  return result;
}

}  // namespace flexmoor::solve
