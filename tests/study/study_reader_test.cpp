// The study reader (apps/study/study_reader.hpp): members expanded from grid: and list:, every
// member's case built and checked before anything runs, and each problem reported as
// STUDY:LINE: what is wrong (got X, expected Y). The line numbers counted in the study texts
// below (title: is line 1, case: line 2) are the reference; no tolerance.
#include "apps/study/study_reader.hpp"

#include <gtest/gtest.h>

#include "apps/problem/case_error.hpp"
#include "apps/study/member_case.hpp"
#include "tests/study/study_cases.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/hanging_masses.hpp"

namespace flexmoor::test {
namespace {

using app::CaseError;
using app::Study;

struct StudyDir {
  std::filesystem::path dir;
  std::string study;
};

StudyDir writeStudy(const std::string& name, const std::string& text) {
  const auto dir = scratch("study-reader-" + name);
  writeOscillatorCase(dir);
  return {dir, writeText(dir, "study.yaml", text).string()};
}

// Every message of the CaseError the study raises, one a line; "" when it reads.
std::string studyErrors(const std::string& name, const std::string& text) {
  const StudyDir s = writeStudy(name, text);
  try {
    app::readStudy(s.study);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

std::string value(const app::StudyMember& m, size_t k) { return m.values.at(k).value.Scalar(); }

TEST(StudyReader, GridIsTheOuterProductLastPathFastest) {
  const StudyDir s = writeStudy("grid", oscillatorStudy(R"(grid:
  loads.gravity.g: [10 m/s^2, 20 m/s^2]
  elements.1.mass: [10 kg, 20 kg, 40 kg]
)"));
  const Study study = app::readStudy(s.study);
  ASSERT_EQ(study.members.size(), 6u);
  EXPECT_EQ(value(study.members[0], 0), "10 m/s^2");
  EXPECT_EQ(value(study.members[0], 1), "10 kg");
  EXPECT_EQ(value(study.members[1], 1), "20 kg");
  EXPECT_EQ(value(study.members[3], 0), "20 m/s^2");
  EXPECT_EQ(value(study.members[3], 1), "10 kg");
  EXPECT_EQ(study.members[5].index, 6);
  ASSERT_EQ(study.parameters.size(), 2u);
  EXPECT_EQ(study.parameters[0].name, "loads_gravity_g");
  EXPECT_EQ(study.parameters[0].units, "m s-2");
  EXPECT_EQ(study.parameters[1].units, "kg");
  EXPECT_DOUBLE_EQ(study.parameters[1].numbers[5], 40.0);
  EXPECT_EQ(study.case_name, "osc");
}

TEST(StudyReader, ListMembersAreEachCrossedWithTheGrid) {
  const StudyDir s = writeStudy("list", oscillatorStudy(R"(list:
  - {elements.1.mass: 20 kg}
  - {elements.1.mass: 5 lbm, loads.gravity.g: 9.81 m/s^2}
grid:
  elements.3.mass: [1 kg, 2 kg]
)"));
  const Study study = app::readStudy(s.study);
  ASSERT_EQ(study.members.size(), 4u);
  EXPECT_EQ(study.members[0].line, 4);  // its list item
  EXPECT_EQ(study.members[2].line, 5);
  EXPECT_EQ(value(study.members[1], 0), "20 kg");
  EXPECT_EQ(value(study.members[1], 1), "2 kg");
  EXPECT_EQ(value(study.members[3], 2), "2 kg");
  // The members that leave a path alone hold the base case's value for it.
  ASSERT_EQ(study.parameters.size(), 3u);
  EXPECT_EQ(study.parameters[2].path, "loads.gravity.g");  // in the order first seen
  EXPECT_EQ(study.parameters[2].texts[0], "10 m/s^2");
  EXPECT_DOUBLE_EQ(study.parameters[0].numbers[2], 5 * 0.45359237);  // 5 lbm in kg
}

TEST(StudyReader, APathTheBaseCaseDoesNotHaveIsAnError) {
  EXPECT_EQ(studyErrors("path", oscillatorStudy("grid:\n  loads.gravity.h: [1, 2]\n")),
            "flexmoor: " + (scratch("study-reader-path") / "study.yaml").string() +
                ":4: grid.loads.gravity.h: not a value of the base case " +
                (scratch("study-reader-path") / "osc.yaml").string() +
                " (got 'loads.gravity.h': no key 'h' in loads.gravity (expected one of: g); a "
                "study varies values the base case gives)");
}

TEST(StudyReader, AListIndexPastTheEndIsAnError) {
  const std::string e = studyErrors("index", oscillatorStudy("grid:\n  elements.9.mass: [1 kg]\n"));
  EXPECT_NE(e.find("study.yaml:4: grid.elements.9.mass: not a value of the base case"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("no item '9' in the list elements (expected an index 0 to 3)"),
            std::string::npos)
      << e;
}

// The member's case reports the value at the base case's line; the study names its own line,
// the member and its values.
TEST(StudyReader, ABadValueNamesTheStudyLineAndTheMember) {
  const std::string e = studyErrors(
      "value", oscillatorStudy("grid:\n  loads.gravity.g:\n    - 10 m/s^2\n    - 10 kg\n"));
  EXPECT_NE(e.find("study.yaml:6: member 2 (loads.gravity.g = 10 kg): the member's case is not "
                   "valid: "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("osc.yaml:17: "), std::string::npos) << e;
  EXPECT_EQ(e.find("member 1"), std::string::npos) << e;  // member 1 is valid
}

// A member whose case fails a check of the built model (a mass of zero on a free dof).
TEST(StudyReader, AMemberThatFailsItsCaseChecksIsAnError) {
  const std::string e =
      studyErrors("check", oscillatorStudy("grid:\n  elements.3.mass: [1 kg, -1 kg]\n"));
  EXPECT_NE(e.find("study.yaml:4: member 2 (elements.3.mass = -1 kg): the member's case is not "
                   "valid: "),
            std::string::npos)
      << e;
}

TEST(StudyReader, AMissingBaseCaseIsAnError) {
  const std::string e = studyErrors("nocase",
                                    "case: nothing.yaml\ngrid: {a: [1]}\ncollect: "
                                    "[{name: x, quantity: speed, node: 1}]\n");
  EXPECT_NE(e.find("study.yaml:1: case: no such file (got 'nothing.yaml', "), std::string::npos)
      << e;
}

TEST(StudyReader, ACollectProblemIsReportedOnceAtItsLine) {
  const std::string e = studyErrors("collect", R"(case: osc.yaml
grid:
  loads.gravity.g: [10 m/s^2, 20 m/s^2]
collect:
  - {name: drop, quantity: displacement_z, node: 9}
)");
  EXPECT_NE(e.find("study.yaml:5: member 1: collect[1].node: "), std::string::npos) << e;
  EXPECT_EQ(e.find("member 2"), std::string::npos) << e;
}

TEST(StudyReader, CollectKeysAreChecked) {
  const std::string e = studyErrors("keys", R"(case: osc.yaml
grid: {loads.gravity.g: [10 m/s^2]}
collect:
  - {name: 1drop, quantity: speed, node: 2}
  - {name: a, quantity: speed, node: 2, statistics: [max, median]}
  - {name: b, quantity: speed, node: 2, statistics: [max, mpm]}
  - {name: c, quantity: speed, node: 2, statistics: [mpm], mpm: {duration: 3 h, fit: normal}}
  - {name: d, quantity: speed, node: 2, stat: max}
  - {name: e, quantity: period, mode: 1}
)");
  EXPECT_NE(e.find("study.yaml:4: collect[1].name: not usable as a variable name (got '1drop'"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("study.yaml:5: collect[2].statistics[2]: "), std::string::npos) << e;
  EXPECT_NE(e.find("study.yaml:6: collect[3]: mpm among the statistics without mpm:"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("study.yaml:7: collect[4].mpm.fit: "), std::string::npos) << e;
}

// Keys of a summary: entry that make no series: read against the case (reported once).
TEST(StudyReader, ASummaryReductionIsNotACollectKey) {
  const std::string e = studyErrors("stat", R"(case: osc.yaml
grid: {loads.gravity.g: [10 m/s^2]}
collect:
  - {name: d, quantity: speed, node: 2, stat: max}
)");
  EXPECT_NE(e.find("study.yaml:4: member 1: collect[1]: unknown key 'stat'"), std::string::npos)
      << e;
}

TEST(StudyReader, MpmIsReadWithItsDurationAndFit) {
  const StudyDir s = writeStudy("mpm", R"(case: osc.yaml
grid: {loads.gravity.g: [10 m/s^2]}
collect:
  - {name: d, quantity: speed, node: 2, statistics: [max, mpm], mpm: {duration: 3 h, fit: gumbel}}
)");
  const Study study = app::readStudy(s.study);
  ASSERT_TRUE(study.collect[0].mpm);
  EXPECT_DOUBLE_EQ(study.collect[0].mpm->duration, 10800.0);
  EXPECT_EQ(study.collect[0].mpm->fit, app::MpmFit::Gumbel);
}

// The hash of a member's case text changes with its own values only.
TEST(StudyReader, MemberHashesFollowTheirValues) {
  const StudyDir a = writeStudy("hash-a", oscillatorStudy("grid:\n  loads.gravity.g: [10 m/s^2, "
                                                          "20 m/s^2]\n"));
  const StudyDir b = writeStudy("hash-b", oscillatorStudy("grid:\n  loads.gravity.g: [10 m/s^2, "
                                                          "30 m/s^2]\n"));
  const Study sa = app::readStudy(a.study), sb = app::readStudy(b.study);
  EXPECT_EQ(sa.members[0].hash, sb.members[0].hash);
  EXPECT_NE(sa.members[1].hash, sb.members[1].hash);
  EXPECT_EQ(sa.members[0].hash.size(), 16u);
}

TEST(StudyReader, CheckCommandValidatesAStudy) {
  const StudyDir good = writeStudy("check-good", oscillatorStudy("grid:\n  loads.gravity.g: [10 "
                                                                 "m/s^2, 20 m/s^2]\n"));
  const CliRun ok = flexmoor("check " + good.study);
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("valid study (2 members of "), std::string::npos) << ok.output;
  const StudyDir bad =
      writeStudy("check-bad", oscillatorStudy("grid:\n  loads.gravity.g: [ten]\n"));
  const CliRun refused = flexmoor("check " + bad.study);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.errors.find("study.yaml:4: member 1 (loads.gravity.g = ten)"),
            std::string::npos)
      << refused.errors;
  const CliRun run = flexmoor("run " + good.study);  // a study is not a case
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.errors.find("is a study, not a case"), std::string::npos) << run.errors;
}

// The named studies of cases/studies/ read, with every member's case built (run by hand:
// docs/performance.md, "Studies").
TEST(StudyReader, NamedStudiesAreValid) {
  for (const auto& [name, members] : {std::pair{"oc4-jonswap", 9u}, std::pair{"tube-rao", 17u}}) {
    const Study s =
        app::readStudy(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/studies/" + name + ".yaml");
    EXPECT_EQ(s.members.size(), members) << name;
  }
  const Study oc4 =
      app::readStudy(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/studies/oc4-jonswap.yaml");
  ASSERT_EQ(oc4.parameters.size(), 3u);
  EXPECT_EQ(oc4.parameters[0].name, "waves_spectrum_Hs");
  EXPECT_EQ(oc4.parameters[0].numbers, (std::vector<double>{2, 2, 2, 4, 4, 4, 6, 6, 6}));
  EXPECT_EQ(oc4.parameters[2].numbers, (std::vector<double>{1, 2, 3, 1, 2, 3, 1, 2, 3}));
  EXPECT_EQ(oc4.parameters[0].units, "m");
  EXPECT_EQ(oc4.parameters[2].units, "1");  // the seed, a count
  EXPECT_EQ(oc4.collect[0].units, "N");
  // Its fairleads by line (line: line_k, end: fairlead): the last element of each line's 12.
  const app::MemberCase member = app::buildMember(oc4, oc4.members[0]);
  ASSERT_EQ(member.collect.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(member.collect[k].element, static_cast<int>(12 * k + 11)) << k;
    EXPECT_EQ(member.collect[k].end, 1) << k;
  }
  // A US case's study: its periods and its statistics in the case's units (the RAO's ft/ft).
  const Study tube =
      app::readStudy(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/studies/tube-rao.yaml");
  EXPECT_EQ(tube.unit_system, "US (ft, slug, s, lbf)");
  EXPECT_EQ(tube.parameters[0].units, "s");
  EXPECT_EQ(tube.collect[1].units, "ft");
}

// The parameters are in the base case's units, the statistics' units: a US case's values given
// in SI units are converted (exact factors: 0.3048 m to the ft, 4.4482216152605 N to the lbf,
// their ratio in kg to the slug; 1e-15 relative), a plain number is the case's own (the mass's
// "1" is 1 slug, the stiffness's "50" 50 lbf/ft), a count has units "1".
TEST(StudyReader, ParametersAreInTheBaseCasesUnits) {
  const auto dir = scratch("study-reader-us-units");
  std::string us = hangingMassesCase();
  us.replace(us.find("units: SI"), 9, "units: US");
  writeText(dir, "osc.yaml",
            us + "  - dynamic: {dt: 0.00314159265359 s, steps: 400, release: [{node: 2, dofs: "
                 "[z]}], tolerance: 1e-8}\n");
  const std::string study = writeText(dir, "study.yaml", oscillatorStudy(R"(list:
  - {loads.gravity.g: 10 m/s^2, elements.1.mass: 10 kg, elements.0.stiffness: 1000 N/m,
     steps.1.dynamic.steps: 400}
  - {loads.gravity.g: 32 ft/s^2, elements.1.mass: 1, elements.0.stiffness: 50,
     steps.1.dynamic.steps: 200}
)"))
                                .string();
  const Study s = app::readStudy(study);
  EXPECT_EQ(s.unit_system, "US (ft, slug, s, lbf)");
  ASSERT_EQ(s.parameters.size(), 4u);
  const auto expect = [](const app::StudyParameter& p, const std::string& units,
                         std::vector<double> values) {
    EXPECT_EQ(p.units, units) << p.path;
    ASSERT_EQ(p.numbers.size(), values.size()) << p.path;
    for (size_t i = 0; i < values.size(); ++i)
      EXPECT_NEAR(p.numbers[i], values[i], 1e-15 * values[i]) << p.path << " " << i;
  };
  expect(s.parameters[0], "ft s-2", {10.0 / 0.3048, 32.0});
  expect(s.parameters[1], "slug", {10.0 / (4.4482216152605 / 0.3048), 1.0});
  expect(s.parameters[2], "lbf ft-1", {1000.0 / 4.4482216152605 * 0.3048, 50.0});
  expect(s.parameters[3], "1", {400.0, 200.0});
  EXPECT_EQ(s.collect[0].units, "ft");
}

}  // namespace
}  // namespace flexmoor::test
