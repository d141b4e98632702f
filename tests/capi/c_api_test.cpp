// The C interface (apps/capi/flexmoor.h) driven as a host program drives it: bad calls and bad
// input are codes with messages, never crashes (this suite also runs under AddressSanitizer); a
// restored checkpoint goes on to the bit; a failed step is recovered from a checkpoint; the
// loads returned are the lines' pull on the platform.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "apps/capi/flexmoor.h"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

bool contains(const char* text, const std::string& part) {
  return std::string(text).find(part) != std::string::npos;
}

// oc4-semi-surge with its platform coupled and started at rest.
flexmoor_t coupledOc4() {
  flexmoor_t h = nullptr;
  EXPECT_EQ(flexmoor_create("oc4-semi-surge", &h), FLEXMOOR_OK) << flexmoor_last_error(h);
  EXPECT_EQ(flexmoor_couple(h, "platform"), FLEXMOOR_OK) << flexmoor_last_error(h);
  const double x[6] = {0, 0, 0, 0, 0, 0}, v[6] = {0, 0, 0, 0, 0, 0};
  EXPECT_EQ(flexmoor_init(h, 6, x, v), FLEXMOOR_OK) << flexmoor_last_error(h);
  return h;
}

// The host's motion: surge 2 sin(2 pi t / 10 s) m, heave 0.5 sin(2 pi t / 14 s) m, pitch
// 2 deg sin(2 pi t / 25 s), all brought in linearly over the first 10 s.
void motion(double t, double* x, double* v) {
  const double pi = std::acos(-1.0), r = std::min(1.0, t / 10.0), dr = t < 10.0 ? 0.1 : 0.0;
  const double w[3] = {2 * pi / 10, 2 * pi / 14, 2 * pi / 25}, a[3] = {2.0, 0.5, 2 * pi / 180};
  const int dof[3] = {0, 2, 4};
  for (int k = 0; k < 6; ++k) x[k] = v[k] = 0.0;
  for (int k = 0; k < 3; ++k) {
    x[dof[k]] = r * a[k] * std::sin(w[k] * t);
    v[dof[k]] = dr * a[k] * std::sin(w[k] * t) + r * a[k] * w[k] * std::cos(w[k] * t);
  }
}

// What a host records of each step: the time, the loads, the first line's fairlead tension.
struct Steps {
  std::vector<double> values;
};

int stepTo(flexmoor_t h, double& t, double end, double dt, Steps* out) {
  double x[6], v[6], f[6];
  while (t < end - 1e-9) {
    motion(t + dt, x, v);
    const int code = flexmoor_step(h, 6, x, v, nullptr, f, &t, dt);
    if (code != FLEXMOOR_OK) return code;
    double tension = 0.0;
    flexmoor_line_end_tension(h, 0, 1, &tension);
    if (out) {
      out->values.push_back(t);
      out->values.insert(out->values.end(), f, f + 6);
      out->values.push_back(tension);
    }
  }
  return FLEXMOOR_OK;
}

// Check CA1. Each wrong call or input: its code, and a message that says what was wrong.
TEST(CApi, BadInputAndBadCallsAreCodesWithMessages) {
  flexmoor_t h = nullptr;
  EXPECT_EQ(flexmoor_create("/nonexistent/no-such-case.yaml", &h), FLEXMOOR_BAD_INPUT);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "no-such-case")) << flexmoor_last_error(h);
  EXPECT_EQ(flexmoor_init(h, 0, nullptr, nullptr), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "not read")) << flexmoor_last_error(h);
  flexmoor_close(h);

  // A case with errors: each FILE:LINE message.
  EXPECT_EQ(flexmoor_create_from_yaml("name: broken\nmaterials:\n  steel: {type: linear_elastic, "
                                      "E: -3}\n",
                                      "broken.yaml", &h),
            FLEXMOOR_BAD_INPUT);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "broken.yaml:3:")) << flexmoor_last_error(h);
  flexmoor_close(h);

  ASSERT_EQ(flexmoor_create("oc4-semi-surge", &h), FLEXMOOR_OK) << flexmoor_last_error(h);
  EXPECT_EQ(flexmoor_couple(h, "hull"), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "platform")) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_couple(h, "platform"), FLEXMOOR_OK);
  EXPECT_EQ(flexmoor_couple(h, "platform"), FLEXMOOR_BAD_CALL);
  double t = 0.0, x[6] = {0}, v[6] = {0}, f[6];
  EXPECT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "before flexmoor_init")) << flexmoor_last_error(h);
  EXPECT_EQ(flexmoor_init(h, 3, x, v), FLEXMOOR_BAD_CALL);  // a wrong number of coupled values
  EXPECT_TRUE(contains(flexmoor_last_error(h), "expected 6")) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_init(h, 6, x, v), FLEXMOOR_OK) << flexmoor_last_error(h);
  EXPECT_EQ(flexmoor_step(h, 5, x, v, nullptr, f, &t, 0.1), FLEXMOOR_BAD_CALL);
  EXPECT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, -0.1), FLEXMOOR_BAD_CALL);
  t = 3.0;  // not the time reached
  EXPECT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1), FLEXMOOR_BAD_CALL);
  x[0] = std::nan("");
  t = 0.0;
  EXPECT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1), FLEXMOOR_BAD_CALL);
  int line_count = 0;
  ASSERT_EQ(flexmoor_line_count(h, &line_count), FLEXMOOR_OK);
  double position[3];
  EXPECT_EQ(flexmoor_line_node_position(h, line_count, 0, position), FLEXMOOR_BAD_CALL);
  EXPECT_EQ(flexmoor_line_node_position(h, 0, 100000, position), FLEXMOOR_BAD_CALL);
  EXPECT_EQ(flexmoor_summary_count(h, &line_count), FLEXMOOR_BAD_CALL);  // before finish
  flexmoor_close(h);
  // A closed handle: a code, not a crash.
  EXPECT_EQ(flexmoor_time(h, &t), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "closed")) << flexmoor_last_error(h);
  flexmoor_close(h);  // twice: nothing
  EXPECT_EQ(flexmoor_create(nullptr, &h), FLEXMOOR_BAD_CALL);
  flexmoor_close(h);
  EXPECT_EQ(flexmoor_create("oc4-semi-surge", nullptr), FLEXMOOR_BAD_CALL);
}

// Check CA2. Save at 30 s, go on to 40 s; restore, go on again: every step's time, loads and
// tension equal to the bit (reference: the first continuation; tolerance 0).
TEST(CApi, ARestoredRunRepeatsItsContinuationToTheBit) {
  flexmoor_t h = coupledOc4();
  double t = 0.0;
  ASSERT_EQ(flexmoor_time(h, &t), FLEXMOOR_OK);
  ASSERT_EQ(stepTo(h, t, 30.0, 0.1, nullptr), FLEXMOOR_OK) << flexmoor_last_error(h);
  flexmoor_checkpoint_t saved = nullptr;
  ASSERT_EQ(flexmoor_save(h, &saved), FLEXMOOR_OK);
  Steps first, again;
  ASSERT_EQ(stepTo(h, t, 40.0, 0.1, &first), FLEXMOOR_OK) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_restore(h, saved), FLEXMOOR_OK) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_time(h, &t), FLEXMOOR_OK);
  EXPECT_EQ(t, 30.0);
  ASSERT_EQ(stepTo(h, t, 40.0, 0.1, &again), FLEXMOOR_OK) << flexmoor_last_error(h);
  ASSERT_EQ(first.values.size(), again.values.size());
  for (size_t k = 0; k < first.values.size(); ++k)
    ASSERT_EQ(first.values[k], again.values[k]) << "value " << k;
  flexmoor_checkpoint_free(saved);
  flexmoor_close(h);
}

// Check CA7. A checkpoint in a file at 30 s, and on to 40 s; a new handle of the same case
// (another process's, as it were) restored from the file goes on to 40 s as the first did, and so
// does the first handle restored from it (reference: the first continuation; tolerance 0). A
// file of another case, a missing file and a file of other bodies are refused with a message.
TEST(CApi, ACheckpointFileGoesOnInAnotherHandleToTheBit) {
  const std::filesystem::path dir = scratch("capi-checkpoint-file");
  const std::string file = (dir / "oc4-30s.checkpoint").string();
  flexmoor_t h = coupledOc4();
  double t = 0.0;
  ASSERT_EQ(stepTo(h, t, 30.0, 0.1, nullptr), FLEXMOOR_OK);
  ASSERT_EQ(flexmoor_save_file(h, file.c_str()), FLEXMOOR_OK) << flexmoor_last_error(h);
  Steps first, other, again;
  ASSERT_EQ(stepTo(h, t, 40.0, 0.1, &first), FLEXMOOR_OK);
  flexmoor_t fresh = coupledOc4();
  ASSERT_EQ(flexmoor_restore_file(fresh, file.c_str()), FLEXMOOR_OK) << flexmoor_last_error(fresh);
  double t_fresh = 0.0;
  ASSERT_EQ(flexmoor_time(fresh, &t_fresh), FLEXMOOR_OK);
  EXPECT_EQ(t_fresh, 30.0);
  ASSERT_EQ(stepTo(fresh, t_fresh, 40.0, 0.1, &other), FLEXMOOR_OK) << flexmoor_last_error(fresh);
  ASSERT_EQ(flexmoor_restore_file(h, file.c_str()), FLEXMOOR_OK) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_time(h, &t), FLEXMOOR_OK);
  ASSERT_EQ(stepTo(h, t, 40.0, 0.1, &again), FLEXMOOR_OK);
  EXPECT_EQ(first.values, other.values);
  EXPECT_EQ(first.values, again.values);
  EXPECT_EQ(flexmoor_restore_file(h, (dir / "missing").c_str()), FLEXMOOR_FAILED);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "missing")) << flexmoor_last_error(h);
  // The crane case: another case, and no body coupled in a handle of OC4 is another body count.
  flexmoor_t plain = nullptr;
  ASSERT_EQ(flexmoor_create("oc4-semi-surge", &plain), FLEXMOOR_OK);
  ASSERT_EQ(flexmoor_init(plain, 0, nullptr, nullptr), FLEXMOOR_OK) << flexmoor_last_error(plain);
  EXPECT_EQ(flexmoor_restore_file(plain, file.c_str()), FLEXMOOR_FAILED);
  EXPECT_TRUE(contains(flexmoor_last_error(plain), "coupled bodies")) << flexmoor_last_error(plain);
  flexmoor_close(plain);
  flexmoor_close(fresh);
  flexmoor_close(h);
}

// Check CA3. An absurd motion (the platform 1,000 km away, held there) makes a step fail
// within three, with a code and a message; the step after it is refused until a restore; after
// the restore the run goes on as if the failed steps had never been tried (reference: a run
// without them; tolerance 0).
TEST(CApi, AFailedStepIsAnErrorAndARestoredHandleGoesOn) {
  flexmoor_t h = coupledOc4(), twin = coupledOc4();
  double t = 0.0, t_twin = 0.0;
  ASSERT_EQ(stepTo(h, t, 5.0, 0.1, nullptr), FLEXMOOR_OK);
  ASSERT_EQ(stepTo(twin, t_twin, 5.0, 0.1, nullptr), FLEXMOOR_OK);
  flexmoor_checkpoint_t saved = nullptr;
  ASSERT_EQ(flexmoor_save(h, &saved), FLEXMOOR_OK);
  double x[6] = {1e6, 0, 0, 0, 0, 0}, v[6] = {0}, f[6];
  int code = FLEXMOOR_OK;
  for (int n = 0; n < 3 && code == FLEXMOOR_OK; ++n)
    code = flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1);
  EXPECT_TRUE(code == FLEXMOOR_NOT_CONVERGED || code == FLEXMOOR_FAILED) << code;
  EXPECT_STRNE(flexmoor_last_error(h), "");
  ASSERT_EQ(flexmoor_time(h, &t), FLEXMOOR_OK);
  EXPECT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(h), "restore")) << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_restore(h, saved), FLEXMOOR_OK);
  ASSERT_EQ(flexmoor_time(h, &t), FLEXMOOR_OK);
  Steps after, reference;
  ASSERT_EQ(stepTo(h, t, 8.0, 0.1, &after), FLEXMOOR_OK) << flexmoor_last_error(h);
  ASSERT_EQ(stepTo(twin, t_twin, 8.0, 0.1, &reference), FLEXMOOR_OK);
  ASSERT_EQ(after.values.size(), reference.values.size());
  for (size_t k = 0; k < after.values.size(); ++k)
    ASSERT_EQ(after.values[k], reference.values[k]) << "value " << k;
  flexmoor_checkpoint_free(saved);
  flexmoor_close(h);
  flexmoor_close(twin);
}

// Check CA4. Two handles on two threads at once give what each gives alone (reference: a run on
// this thread; tolerance 0): handles share nothing.
TEST(CApi, HandlesOnSeparateThreadsAreIndependent) {
  Steps alone;
  {
    flexmoor_t h = coupledOc4();
    double t = 0.0;
    ASSERT_EQ(stepTo(h, t, 5.0, 0.1, &alone), FLEXMOOR_OK);
    flexmoor_close(h);
  }
  Steps a, b;
  const auto run = [](Steps* out) {
    flexmoor_t h = coupledOc4();
    double t = 0.0;
    stepTo(h, t, 5.0, 0.1, out);
    flexmoor_close(h);
  };
  std::thread first(run, &a), second(run, &b);
  first.join();
  second.join();
  EXPECT_EQ(a.values, alone.values);
  EXPECT_EQ(b.values, alone.values);
}

// A body `crane` carrying a hook 10 m from its reference point (the origin), a 2 kg mass hung
// from the hook on a spring, in air, guided vertically under where a pitch of 0.1 rad puts the
// hook (x = 10 cos 0.1 m).
const char kCrane[] = R"(name: crane
units: SI
nodes:
  1: [10 m, 0, 0]
  2: [9.950041652780258 m, 0, -5 m]
elements:
  - {type: spring, nodes: [1, 2], stiffness: 1000 N/m, compression: carry}
  - {type: point_mass, node: 2, mass: 2 kg}
histories:
  crane: {type: rigid_motion}
  hook_x: {type: rigid_point, motion: crane, arm: [10 m, 0, 0], component: x}
  hook_y: {type: rigid_point, motion: crane, arm: [10 m, 0, 0], component: y}
  hook_z: {type: rigid_point, motion: crane, arm: [10 m, 0, 0], component: z}
supports:
  - {node: 1, fix: [x], displacement: [1], history: hook_x}
  - {node: 1, fix: [y], displacement: [1], history: hook_y}
  - {node: 1, fix: [z], displacement: [1], history: hook_z}
  - {node: 2, fix: [x, y]}
loads:
  gravity: {g: 9.81}
steps:
  - static: {name: hung}
  - dynamic: {name: held, dt: 0.01 s, steps: 100}
)";

// Check CA5. The loads on a body are the pull of what hangs from it and the moment of that pull
// about its reference point where the body is: a crane pitched by 0.1 rad holding a 2 kg mass,
// at rest and after 0.5 s held still: force (0, 0, -m g), moment (0, 10 m g cos 0.1, 0) about the
// origin (reference: those closed forms; tolerance 1e-9 of m g, Newton's).
TEST(CApi, LoadsOnABodyAreThePullOfWhatHangsFromItAndItsMoment) {
  flexmoor_t h = nullptr;
  ASSERT_EQ(flexmoor_create_from_yaml(kCrane, "crane.yaml", &h), FLEXMOOR_OK)
      << flexmoor_last_error(h);
  ASSERT_EQ(flexmoor_couple(h, "crane"), FLEXMOOR_OK) << flexmoor_last_error(h);
  const double pitch = 0.1, mg = 2.0 * 9.81;
  const double x[6] = {0, 0, 0, 0, pitch, 0}, v[6] = {0, 0, 0, 0, 0, 0};
  ASSERT_EQ(flexmoor_init(h, 6, x, v), FLEXMOOR_OK) << flexmoor_last_error(h);
  double f[6], t = 0.0;
  ASSERT_EQ(flexmoor_coupled_loads(h, f), FLEXMOOR_OK);
  for (int pass = 0; pass < 2; ++pass) {
    EXPECT_NEAR(f[0], 0.0, 1e-9 * mg);
    EXPECT_NEAR(f[1], 0.0, 1e-9 * mg);
    EXPECT_NEAR(f[2], -mg, 1e-9 * mg);
    EXPECT_NEAR(f[3], 0.0, 1e-9 * mg);
    EXPECT_NEAR(f[4], 10.0 * mg * std::cos(pitch), 1e-8 * mg);
    EXPECT_NEAR(f[5], 0.0, 1e-9 * mg);
    for (int n = 0; n < 5; ++n) ASSERT_EQ(flexmoor_step(h, 6, x, v, nullptr, f, &t, 0.1), 0);
  }
  double hook[3];
  ASSERT_EQ(flexmoor_node_positions(h, nullptr), FLEXMOOR_BAD_CALL);
  double nodes[6];
  ASSERT_EQ(flexmoor_node_positions(h, nodes), FLEXMOOR_OK);
  hook[0] = nodes[0], hook[2] = nodes[2];
  EXPECT_NEAR(hook[0], 10.0 * std::cos(pitch), 1e-12);  // the hook where the pitch put it
  EXPECT_NEAR(hook[2], -10.0 * std::sin(pitch), 1e-12);
  flexmoor_close(h);
}

// Check CA9. OC4's three fairleads coupled as points, moved by the host as the platform's surge
// moves them (x = the fairlead's place + s(t), surge only: s = 2 sin(2 pi t / 10 s) m brought in
// over 10 s), give the run of the coupled platform: each point's load is its line's pull, whose
// sum is the platform's force (1e-11 of the largest, measured 1.7e-12), and line 1's fairlead
// tension follows (1e-11 relative, measured 9.4e-13): the two differ by the round-off of a point's
// place plus its motion less its place. Coupling mistakes are codes with messages:
// a line's middle, an unknown line, a point the coupled platform carries.
TEST(CApi, CoupledFairleadPointsMoveAsThePlatformThatCarriesThem) {
  const double place[9] = {20.434, 35.393, -14.0, -40.868, 0.0, -14.0, 20.434, -35.393, -14.0};
  const auto surge = [](double t, double& s, double& ds) {
    const double pi = std::acos(-1.0), r = std::min(1.0, t / 10.0), dr = t < 10.0 ? 0.1 : 0.0;
    s = r * 2.0 * std::sin(2 * pi * t / 10.0);
    ds = dr * 2.0 * std::sin(2 * pi * t / 10.0) +
         r * 2.0 * (2 * pi / 10.0) * std::cos(2 * pi * t / 10.0);
  };
  flexmoor_t body = nullptr, points = nullptr;
  ASSERT_EQ(flexmoor_create("oc4-semi-surge", &body), FLEXMOOR_OK) << flexmoor_last_error(body);
  ASSERT_EQ(flexmoor_couple(body, "platform"), FLEXMOOR_OK) << flexmoor_last_error(body);
  EXPECT_EQ(flexmoor_couple(body, "line_1.fairlead"), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(body), "is carried by the coupled body 'platform'"))
      << flexmoor_last_error(body);
  ASSERT_EQ(flexmoor_create("oc4-semi-surge", &points), FLEXMOOR_OK) << flexmoor_last_error(points);
  EXPECT_EQ(flexmoor_couple(points, "line_1.middle"), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(points), "not an end of line line_1"))
      << flexmoor_last_error(points);
  EXPECT_EQ(flexmoor_couple(points, "line_9.fairlead"), FLEXMOOR_BAD_CALL);
  EXPECT_TRUE(contains(flexmoor_last_error(points), "no line named 'line_9'"))
      << flexmoor_last_error(points);
  for (const char* name : {"line_1.fairlead", "line_2.fairlead", "line_3.fairlead"})
    ASSERT_EQ(flexmoor_couple(points, name), FLEXMOOR_OK) << flexmoor_last_error(points);
  int dofs = 0;
  ASSERT_EQ(flexmoor_coupled_dofs(points, &dofs), FLEXMOOR_OK);
  ASSERT_EQ(dofs, 9);

  double xb[6] = {0, 0, 0, 0, 0, 0}, vb[6] = {0, 0, 0, 0, 0, 0}, xp[9], vp[9] = {};
  std::copy(place, place + 9, xp);
  ASSERT_EQ(flexmoor_init(body, 6, xb, vb), FLEXMOOR_OK) << flexmoor_last_error(body);
  ASSERT_EQ(flexmoor_init(points, 9, xp, vp), FLEXMOOR_OK) << flexmoor_last_error(points);
  double tb = 0.0, tp = 0.0, fb[6], fp[9], worst_force = 0.0, worst_tension = 0.0;
  for (int n = 1; n <= 200; ++n) {
    double s, ds;
    surge(0.1 * n, s, ds);
    xb[0] = s, vb[0] = ds;
    for (int p = 0; p < 3; ++p) xp[3 * p] = place[3 * p] + s, vp[3 * p] = ds;
    ASSERT_EQ(flexmoor_step(body, 6, xb, vb, nullptr, fb, &tb, 0.1), FLEXMOOR_OK)
        << flexmoor_last_error(body);
    ASSERT_EQ(flexmoor_step(points, 9, xp, vp, nullptr, fp, &tp, 0.1), FLEXMOOR_OK)
        << flexmoor_last_error(points);
    const double scale = Eigen::Map<const Eigen::VectorXd>(fp, 9).cwiseAbs().maxCoeff();
    for (int k = 0; k < 3; ++k)
      worst_force = std::max(worst_force, std::abs(fp[k] + fp[3 + k] + fp[6 + k] - fb[k]) / scale);
    double tension_b = 0.0, tension_p = 0.0;
    ASSERT_EQ(flexmoor_line_end_tension(body, 0, 1, &tension_b), FLEXMOOR_OK);
    ASSERT_EQ(flexmoor_line_end_tension(points, 0, 1, &tension_p), FLEXMOOR_OK);
    worst_tension = std::max(worst_tension, std::abs(tension_p / tension_b - 1.0));
  }
  RecordProperty("worst_force", std::to_string(worst_force));
  RecordProperty("worst_tension", std::to_string(worst_tension));
  EXPECT_LT(worst_force, 1e-11);
  EXPECT_LT(worst_tension, 1e-11);
  std::cout << "[ CApi ] points against the body: force " << worst_force << ", tension "
            << worst_tension << "\n";
  flexmoor_close(body);
  flexmoor_close(points);
}

}  // namespace
}  // namespace flexmoor::test
