// `flexmoor study` end to end on the oscillator of study_cases.hpp: members on worker
// processes, a member that fails on purpose, resuming, study.nc as xarray reads it, and the
// statistics of the released mass against their closed forms.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "apps/output/output_lock.hpp"
#include "apps/study/member_store.hpp"
#include "apps/study/series_file.hpp"
#include "apps/study/study_statistics.hpp"
#include "libhydro/signal/extremes.hpp"
#include "tests/study/study_cases.hpp"
#include "tests/study/study_netcdf.hpp"
#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;

// g = 10 and 20 m/s^2 crossed with at most 30 Newton iterations a time step (converges) and 1
// (the first increment of a step is the step's whole motion, never within the displacement
// tolerance, nor after any number of halvings: exit 3).
const char* kFailingGrid = R"(grid:
  loads.gravity.g: [10 m/s^2, 20 m/s^2]
  steps.1.dynamic.max_iterations: [30, 1]
)";

fs::path studyDir(const std::string& name, const std::string& variations) {
  const fs::path dir = scratch("study-run-" + name);
  writeOscillatorCase(dir);
  writeText(dir, "study.yaml", oscillatorStudy(variations));
  return dir;
}

CliRun runStudy(const fs::path& dir, const std::string& extra = "-j 2") {
  return flexmoor("study " + (dir / "study.yaml").string() + " -o " + (dir / "out").string() + " " +
                  extra);
}

TEST(StudyRun, AFailingMemberLeavesTheOthersComplete) {
  const fs::path dir = studyDir("failing", kFailingGrid);
  const CliRun r = runStudy(dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;  // some member failed
  const fs::path out = dir / "out";
  EXPECT_EQ(intVariable(out / "study.nc", "status"), (std::vector<int>{0, 3, 0, 3}));
  for (const char* m : {"0001", "0003"}) {
    EXPECT_TRUE(fs::exists(out / "members" / m / "complete")) << m;
    EXPECT_TRUE(fs::exists(out / "members" / m / "series.nc")) << m;
    EXPECT_TRUE(fs::exists(out / "members" / m / "osc.nc")) << m;
  }
  EXPECT_NE(readFile(out / "members/0002/failed").find("did not converge"), std::string::npos);
  const std::vector<double> max = doubleVariable(out / "study.nc", "drop_max");
  EXPECT_FALSE(std::isnan(max[0]));
  EXPECT_TRUE(std::isnan(max[1]));  // _FillValue, read back as NaN
  EXPECT_NE(textRow(out / "study.nc", "error", 1).find("exit code 3"), std::string::npos);
  EXPECT_EQ(textRow(out / "study.nc", "error", 0), "");
  EXPECT_NE(r.output.find("1 failed"), std::string::npos) << r.output;  // progress
}

// The first child process of `pid` (from /proc), or 0 while there is none.
pid_t firstChild(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  pid_t child = 0;
  return in >> child ? child : 0;
}

// A worker killed by a signal (as by the kernel's OOM killer or a user): its member is failed
// with the signal's name, and the study goes on to the next member. Member 1 would run 400,000
// time steps; on one worker it is killed as soon as its worker exists.
TEST(StudyRun, AKilledWorkerIsRecordedAndTheOthersRun) {
  const fs::path dir = studyDir("killed", "grid:\n  steps.1.dynamic.steps: [400000, 400]\n");
  const std::string study = (dir / "study.yaml").string(), out = (dir / "out").string();
  const std::string log = (dir / "study.log").string();
  std::vector<std::string> args = {FLEXMOOR_BINARY, "study", study, "-o", out, "-j", "1"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT, 0644);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&files);
  pid_t worker = 0;
  for (int i = 0; i < 2000 && !worker; ++i) {  // up to 20 s for the study's checks
    worker = firstChild(pid);
    if (!worker) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_NE(worker, 0);
  kill(worker, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_EQ(WEXITSTATUS(status), 4) << readFile(log);
  EXPECT_EQ(intVariable(dir / "out/study.nc", "status"), (std::vector<int>{4, 0}));
  EXPECT_NE(textRow(dir / "out/study.nc", "error", 0).find("killed by signal 9 (Killed)"),
            std::string::npos)
      << textRow(dir / "out/study.nc", "error", 0);
}

// A second study into a directory while one runs there is refused, writing nothing.
TEST(StudyRun, ASecondStudyIntoTheSameDirectoryIsRefused) {
  const fs::path dir = studyDir("locked", "grid:\n  loads.gravity.g: [10 m/s^2]\n");
  fs::create_directories(dir / "out");
  const app::OutputLock held((dir / "out/.study.lock").string(), "held by the test");
  const CliRun r = runStudy(dir);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.errors.find("another study is running there"), std::string::npos) << r.errors;
  EXPECT_FALSE(fs::exists(dir / "out/members"));
}

// A rerun skips what is complete (its marker untouched) and runs a member whose value changed.
TEST(StudyRun, ARerunSkipsCompleteMembersAndRerunsChangedOnes) {
  const fs::path dir = studyDir("resume", "grid:\n  loads.gravity.g: [10 m/s^2, 20 m/s^2]\n");
  ASSERT_EQ(runStudy(dir).exit_code, 0);
  const fs::path m1 = dir / "out/members/0001/complete", m2 = dir / "out/members/0002/complete";
  const auto t1 = fs::last_write_time(m1), t2 = fs::last_write_time(m2);
  const CliRun again = runStudy(dir);
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("2 complete already, 0 to run"), std::string::npos) << again.output;
  EXPECT_EQ(fs::last_write_time(m1), t1);
  EXPECT_EQ(fs::last_write_time(m2), t2);
  writeText(dir, "study.yaml", oscillatorStudy("grid:\n  loads.gravity.g: [10 m/s^2, 30 m/s^2]\n"));
  const CliRun changed = runStudy(dir);
  EXPECT_EQ(changed.exit_code, 0) << changed.output;
  EXPECT_NE(changed.output.find("1 complete already, 1 to run"), std::string::npos)
      << changed.output;
  EXPECT_EQ(fs::last_write_time(m1), t1);
  EXPECT_NE(readFile(m2), "");
  // The changed member's amplitude m g / k follows its new g: 10 kg 30 m/s^2 / 1000 N/m.
  EXPECT_NEAR(doubleVariable(dir / "out/study.nc", "drop_amplitude")[1], 0.3, 1e-6);
}

// The released mass: z(t) = -(m g / k)(1 - cos(omega t)) over two periods of 200 steps. Its
// amplitude is m g / k; mean -m g / k; std (m g / k) / sqrt(2) (summary_series.hpp's closed
// forms for a sampled cosine over whole periods). The trapezoidal rule lengthens the period by
// (omega dt)^2 / 12 = 8.2e-5 of it, so the run's two periods end short of the series' end: the
// mean moves by 8.2e-5 of m g / k and the std by 4.1e-5 (measured), the amplitude by 1.7e-8:
// tolerances 1e-4, 5e-5 and 5e-8 relative.
TEST(StudyRun, StatisticsOfTheReleasedMassMatchTheirClosedForms) {
  const fs::path dir = studyDir("closed-forms", "grid:\n  loads.gravity.g: [10 m/s^2, 20 m/s^2]\n");
  ASSERT_EQ(runStudy(dir).exit_code, 0);
  const fs::path nc = dir / "out/study.nc";
  const auto amplitude = doubleVariable(nc, "drop_amplitude"),
             mean = doubleVariable(nc, "drop_mean"), std = doubleVariable(nc, "drop_std"),
             max = doubleVariable(nc, "drop_max");
  for (int i = 0; i < 2; ++i) {
    const double a = 10.0 * 10.0 * (i + 1) / 1000.0;  // m g / k
    EXPECT_NEAR(amplitude[i], a, 5e-8 * a) << i;
    EXPECT_NEAR(mean[i], -a, 1e-4 * a) << i;
    EXPECT_NEAR(std[i], a / std::sqrt(2.0), 5e-5 * a) << i;
    EXPECT_NEAR(max[i], 0.0, 1e-12) << i;  // the start, at rest
  }
  // The spectrum on one axis: a one-period segment (0.628 s) gives bins of 10 rad/s, the
  // response's own circular frequency is bin 1, where the density peaks.
  const std::vector<double> omega = doubleVariable(nc, "frequency");
  ASSERT_GT(omega.size(), 3u);
  EXPECT_NEAR(omega[1], 10.0, 1e-9);
  const std::vector<double> psd = doubleVariable(nc, "drop_psd");
  const size_t bins = omega.size();
  for (size_t k = 2; k < bins; ++k) EXPECT_LT(psd[k], psd[1]) << k;
}

// NAME_mpm is the most probable maximum of each member's series (libhydro/signal/extremes.hpp,
// checked there against Rayleigh's closed form), with its settings as attributes: study.nc
// holds, bit for bit, mostProbableMaximum of the member's series.nc resampled at its step. The
// released mass swings a sine of amplitude a = m g / k about -a for 64 periods, so its peaks are
// all 0 (to the sampling of the step) and so is the most probable maximum of any duration:
// measured 2.3e-5 a; tolerance 1e-4 a.
TEST(StudyRun, MostProbableMaximumOfEachMemberFromItsSeries) {
  const fs::path dir = scratch("study-run-mpm");
  writeOscillatorCase(dir);
  std::string base;
  {
    std::ifstream in(dir / "osc.yaml");
    base.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string from = "steps: 400,";
  base.replace(base.find(from), from.size(), "steps: 12800,");
  writeText(dir, "osc.yaml", base);
  writeText(dir, "study.yaml", R"(title: mpm
case: osc.yaml
grid:
  loads.gravity.g: [10 m/s^2, 20 m/s^2]
collect:
  - {name: drop, quantity: displacement_z, node: 2, statistics: [max, mpm],
     mpm: {duration: 600 s, fit: weibull}}
)");
  ASSERT_EQ(runStudy(dir).exit_code, 0);
  const fs::path nc = dir / "out/study.nc";
  const std::vector<double> mpm = doubleVariable(nc, "drop_mpm");
  ASSERT_EQ(mpm.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const app::SeriesData s =
        app::readSeriesFile(app::seriesPath((dir / "out").string(), i + 1), {"drop"});
    const std::vector<double>& v = s.variables[0].values;
    const double dt = app::medianStep(s.time, v);
    EXPECT_EQ(mpm[i], signal::mostProbableMaximum(app::resampled(s.time, v, dt), dt, 600.0,
                                                  signal::ExtremeFit::Weibull))
        << i;
    const double a = 10.0 * 10.0 * (i + 1) / 1000.0;  // m g / k
    EXPECT_NEAR(mpm[i], 0.0, 1e-4 * a) << i;
  }
}

// study.nc as xarray reads it: the parameters are coordinates of the statistics, with their
// units and paths; status carries its flags; failed members are NaN (their _FillValue); the
// statistics and the parameters in the base case's units, which the file names.
TEST(StudyRun, XarrayReadsStudyNcWithTheParametersAsCoordinates) {
  const fs::path dir = studyDir("xarray", kFailingGrid);
  runStudy(dir);
  const std::string script = R"(
import sys, xarray as xr, numpy as np
d = xr.open_dataset(sys.argv[1])
v = d['drop_max']
print('coords', sorted(c for c in v.coords))
print('units', d['loads_gravity_g'].attrs['units'], d['loads_gravity_g'].attrs['flexmoor_path'])
print('g', list(d['loads_gravity_g'].values))
print('params', d.attrs['study_parameters'])
print('flags', d['status'].attrs['flag_meanings'])
print('nan', list(np.isnan(v.values)))
print('psd', d['drop_psd'].dims, d['frequency'].attrs['units'])
print('stat units', v.attrs['units'], d['steps_1_dynamic_max_iterations'].attrs['units'],
      d.attrs['unit_system'])
)";
  writeText(dir, "check.py", script);
  const std::string cmd = "/usr/bin/python3 " + (dir / "check.py").string() + " " +
                          (dir / "out/study.nc").string() + " 2>&1";
  std::string text;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[512];
  while (fgets(buf, sizeof buf, p)) text += buf;
  EXPECT_EQ(pclose(p), 0) << text;
  EXPECT_NE(text.find("coords ['loads_gravity_g', 'member', 'steps_1_dynamic_max_iterations']"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("units m s-2 loads.gravity.g"), std::string::npos) << text;
  EXPECT_NE(text.find("g [10.0, 10.0, 20.0, 20.0]"), std::string::npos) << text;
  EXPECT_NE(text.find("params loads_gravity_g steps_1_dynamic_max_iterations"), std::string::npos)
      << text;
  EXPECT_NE(text.find("flags complete bad_input not_converged failed"), std::string::npos) << text;
  EXPECT_NE(text.find("nan [False, True, False, True]"), std::string::npos) << text;
  EXPECT_NE(text.find("psd ('member', 'frequency') rad s-1"), std::string::npos) << text;
  // Every variable states its units, the base case's (SI here): a count or ratio "1".
  EXPECT_NE(text.find("stat units m 1 SI (m, kg, s, N)"), std::string::npos) << text;
}

// A 2-rank MPI run and a 2-worker local run give the same study.nc: every double variable
// equal bit for bit (the members' runs are the same computations in the same order; rank 0
// writes study.nc from the members' files as the local run does).
TEST(StudyRun, TwoMpiRanksAndTwoLocalWorkersGiveTheSameStudy) {
#ifndef FLEXMOOR_MPIEXEC
  GTEST_SKIP() << "built without MPI (FLEXMOOR_MPI off)";
#else
  const fs::path local = studyDir("mpi-local", kFailingGrid);
  const fs::path mpi = studyDir("mpi-ranks", kFailingGrid);
  EXPECT_EQ(runStudy(local).exit_code, 4);
  // As root OpenMPI refuses to start without these; 2 ranks on fewer cores need oversubscribe.
  // Under the sanitizer build, OpenMPI's own allocations that live until exit are not leaks of
  // flexmoor's: the leak check is off for the ranks (the other checks stay on).
  const std::string cmd =
      std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
      "ASAN_OPTIONS=detect_leaks=0:check_initialization_order=1 " + FLEXMOOR_MPIEXEC +
      " --oversubscribe -n 2 " + FLEXMOOR_BINARY + " study " + (mpi / "study.yaml").string() +
      " -o " + (mpi / "out").string() + " > " + (mpi / "mpirun.log").string() + " 2>&1";
  std::system(cmd.c_str());  // exit 4 (a member failed), which mpirun reports as its own
  ASSERT_TRUE(fs::exists(mpi / "out/study.nc")) << readFile(mpi / "mpirun.log");
  EXPECT_NE(readFile(mpi / "mpirun.log").find("over 2 MPI ranks"), std::string::npos);
  const auto a = doubleVariables(local / "out/study.nc");
  const auto b = doubleVariables(mpi / "out/study.nc");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), 7u);  // 2 parameters, 5 statistics, the frequency axis and the spectra
  for (const auto& [name, values] : a) {
    ASSERT_TRUE(b.count(name)) << name;
    EXPECT_TRUE(sameBits(values, b.at(name))) << name;
  }
  EXPECT_EQ(intVariable(mpi / "out/study.nc", "status"), (std::vector<int>{0, 3, 0, 3}));
#endif
}

}  // namespace
}  // namespace flexmoor::test
