#pragma once
// The sums of component_sums.hpp for a long-crested sea (every component along one heading d)
// under one envelope for all components (no front: the ramp's E(t) and dE/dt, or none): the
// same linear kinematics, summed without the heading's products. Each of the 26 sums of the
// general case is then d_x, d_y or a product of two times one of eleven sums over the
// components (docs/theory.md's terms with E and d taken out), and u's d/dtheta is w's d/dz (and so
// on for the other pairs), so a point costs 11 reductions instead of 15 terms and 26 dot
// products; the results differ from the general sums by round-off (the sums' order).
//
// Deep down, the short waves are not felt: where the components are in order of k (a
// synthesised sea's are), those whose depth factors are all below 2^-59 at the point are left
// out of the kinematics (not of the elevation), each term of them below 2^-59 of its
// component's surface value, so the sums change by less than 2^-59 of the sum of the
// components' a w^2 (and likewise for the other terms): below round-off. At 100 m, the waves
// shorter than 15 m (k > 0.42 / m); over the OC4 lines, a third of a JONSWAP sea's components.
#include "libhydro/waves/component_sums.hpp"

namespace flexmoor::hydro {

// The elevation E sum a_i cos(theta_i), and with `gradient` its horizontal gradient
// -E d sum k_i a_i sin(theta_i) (the phases in s, from componentPhases).
double longCrestedElevation(const ComponentTable& c, const ComponentScratch& s, const Envelope& e,
                            Eigen::Vector3d* gradient);
// The kinematics at depth z (z <= 0), and with `gradients` their partial derivatives, into `out`
// (which they replace), as kinematicsSum gives them for a long-crested sea whose envelope is e
// at every component (value and rate; its slopes must be zero), over a bed at `depth` (the
// table's; infinite for deep water).
void longCrestedKinematics(const ComponentTable& c, ComponentScratch& s, const Envelope& e,
                           double z, double depth, bool gradients, LinearKinematics& out);
// How many of the components (the first ones) are felt at depth z (z <= 0), as above: all of
// them unless k ascends; of those, the ones with k < ln(2^60) / min(-z, 2 depth + z).
std::size_t componentsFelt(const ComponentTable& c, double z, double depth);

}  // namespace flexmoor::hydro
