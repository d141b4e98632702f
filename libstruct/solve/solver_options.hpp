#pragma once
// Options of the static solvers, as a case file states them.
namespace flexmoor::solve {

enum class NewtonFlavour {
  Full,      // Newton-Raphson: tangent updated every iteration
  Modified,  // modified Newton: tangent updated every `stiffness_update` iterations and at the
             // start of every increment
};

// Convergence (Eq. 5.1): sqrt(sum du^2 / sum u^2) < displacement_tolerance, and/or
// |R| < residual_tolerance * max(|P|, |F|) over the free dofs.
struct Convergence {
  bool use_displacement = true;
  bool use_residual = true;
  double displacement_tolerance = 1e-6;
  double residual_tolerance = 1e-8;
};

struct StaticOptions {
  double load_factor = 1.0;  // target load factor, reached from the current one
  int increments = 1;
  NewtonFlavour flavour = NewtonFlavour::Full;
  int stiffness_update = 1;  // modified Newton: iterations between tangent updates
  int max_iterations = 50;
  Convergence convergence;
};

// Viscous relaxation (Appendix C): D u' + F(u) = P with D = C I, implicit steps of unit
// pseudo-time, C reduced after each step.
struct RelaxationOptions {
  double load_factor = 1.0;
  double tolerance = 1e-3;              // Eq. C.15 on the step's displacement change
  double damping = 1.0e4;               // C, the damping matrix constant (Eq. C.11)
  double initial_damping_factor = 0.01; // mu0 of Eq. C.13, the floor of one step's reduction
  double decrement = 1.0;               // gamma of Eq. C.13, exponent on the convergence ratio
  double residual_tolerance = 1e-8;     // equilibrium check: |R| < tol * max(|P|, |F|)
  int max_steps = 500;
  int max_iterations = 30;              // Newton iterations inside one pseudo-time step
};

}  // namespace flexmoor::solve
