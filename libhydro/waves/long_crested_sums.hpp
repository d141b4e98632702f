#pragma once
// The sums of component_sums.hpp for a long-crested sea (every component along one heading d)
// under one envelope for all components (no front: the ramp's E(t) and dE/dt, or none): the
// same linear kinematics, summed without the heading's products. Each of the 26 sums of the
// general case is then d_x, d_y or a product of two times one of eleven sums over the
// components (hydro.md's terms with E and d taken out), and u's d/dtheta is w's d/dz (and so
// on for the other pairs), so a point costs 11 reductions instead of 15 terms and 26 dot
// products; the results differ from the general sums by round-off (the sums' order).
#include "libhydro/waves/component_sums.hpp"

namespace flexmoor::hydro {

// The elevation E sum a_i cos(theta_i), and with `gradient` its horizontal gradient
// -E d sum k_i a_i sin(theta_i) (the phases in s, from componentPhases).
double longCrestedElevation(const ComponentTable& c, const ComponentScratch& s, const Envelope& e,
                            Eigen::Vector3d* gradient);
// The kinematics at depth z (z <= 0), and with `gradients` their partial derivatives, into `out`
// (which they replace), as kinematicsSum gives them for a long-crested sea whose envelope is e
// at every component (value and rate; its slopes must be zero).
void longCrestedKinematics(const ComponentTable& c, ComponentScratch& s, const Envelope& e,
                           double z, bool gradients, LinearKinematics& out);

}  // namespace flexmoor::hydro
