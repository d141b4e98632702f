#pragma once
// scenario: spread_mooring as specifications: N mooring lines from anchors to fairlead points, in
// water with seabed contact, stated by a program (spreadMooring) or read from a case file's few
// keys (readSpreadMooring, read_spread_mooring.cpp). OC3-Hywind and OC4-DeepCwind (cases/ocean)
// are such cases.
//
// Line k (1-based) is line_k, a mooring line (its anchor line_k.start, its fairlead line_k.end):
// its reference the straight line of its unstretched length laid along the bed from its anchor
// towards its fairlead, one line of its type or its segments line_k_segment_1, ... (each a
// segment of line_k starting at the end of the one before), started on the elastic catenary of
// the whole line with seabed contact (CatenaryStartSpec). An attachment at connection k (between
// segments k and k + 1) is a point mass of its mass and a point body of its volume: a net upward
// force (rho V - m) g, with the body's Morison loads in motion. The anchor is held; the fairlead
// is held where the spec puts it, or, with a platform, each of its dofs follows the platform's
// point there (model::RigidPointMotion): its rest position plus the platform's motion, whose
// velocity and acceleration are those of the rigid motion (v + omega x r); the statics hold the
// platform where its motion puts it at t = 0.
//
// The default summary, per line, in the state that closes the static step (the last step before
// the first dynamic one): fairlead_tension_static_k and anchor_tension_static_k (the force on the
// end point from the end element's nodal force balance, end_tension), fairlead_horizontal_static_k
// and fairlead_vertical_static_k (the fairlead support's reaction: the upward pull that holds the
// line), anchor_horizontal_static_k and anchor_vertical_static_k (the line's pull on the anchor,
// upward +; a laid line's anchor, held at the bed's level, carries a little of the laid part's
// weight, a small negative value) and length_on_seabed_static_k; with a dynamic step, over the
// last one: fairlead_tension_max_k, fairlead_tension_min_k, anchor_tension_max_k and
// anchor_vertical_max_k (the largest uplift).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/case/scenarios/mooring_lines.hpp"
#include "apps/case/scenarios/platform.hpp"
#include "apps/problem/case_spec.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libhydro/water/water.hpp"

namespace flexmoor::app {

struct SpreadMooringSpec {
  UnitSystem units = UnitSystem::SI;
  hydro::Water water;  // its density, its depth (the bed flat there) and gravity
  hydro::SeabedProperties seabed;
  std::map<std::string, LineType> line_types;
  std::vector<MooringLine> lines;  // line_1, line_2, ...
  std::optional<PlatformSpec> platform;
};

// The case: the lines, their supports, the ocean (the water, seabed contact, Morison loads of the
// line types, the attachments' bodies), the lines' catenary starts, the platform's motion (the
// rigid motion `platform`), `steps` (none: the static step `equilibrium`, Newton from the
// catenaries at the full load in one increment), the default summary and a mooring figure.
CaseSpec spreadMooring(const SpreadMooringSpec& spec, std::vector<StepSpec> steps = {});

// The default summary of a spread mooring's case (its lines line_1, ... and its steps).
std::vector<SummarySpec> spreadMooringSummary(const CaseSpec& c);

// The static step a spread mooring starts with: Newton from the catenaries at the full load, one
// increment, named `equilibrium`.
StepSpec spreadMooringStatics();

}  // namespace flexmoor::app
