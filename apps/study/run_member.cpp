#include "apps/study/run_member.hpp"

#include <iostream>

#include "apps/problem/case_error.hpp"
#include "apps/run/run_case.hpp"
#include "apps/study/member_case.hpp"
#include "apps/study/member_store.hpp"
#include "apps/study/series_file.hpp"
#include "apps/study/series_recorder.hpp"

namespace flexmoor::app {

int runMember(const Study& study, const StudyMember& member, const std::string& dir) {
  try {
    const MemberCase m = buildMember(study, member);
    SeriesRecorder recorder(m.c, m.collect);
    RunOptions options;
    options.output_dir = memberDirectory(dir, member.index);
    options.vtk = false;
    options.figure = false;
    options.background_writer = false;  // the members fill the cores
    options.observers.push_back(&recorder);
    const RunOutcome outcome = runCase(m.c, options, std::cout, std::cerr);
    if (outcome.exit_code != kSuccess) return outcome.exit_code;
    writeSeriesFile(seriesPath(dir, member.index), recorder, unitNames(m.c.units).time);
    markComplete(dir, member);
    return kSuccess;
  } catch (const CaseError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: " << e.what() << "\n";
    return kRunFailed;
  }
}

}  // namespace flexmoor::app
