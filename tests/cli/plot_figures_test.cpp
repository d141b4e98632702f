// The figures (`flexmoor plot`, apps/plot/flexmoor_plot.py): a series' spectrum
// against its sea's target, line shapes at chosen times, and from a study's DIR/study.nc
// (written here in the format `flexmoor study` writes, writeStudy below) a response-amplitude
// curve, extremes against Hs and the members' response spectra; each a PNG of the size asked for, and bad arguments refused
// with a message and exit code 2. The plot's own JONSWAP and Welch estimate are checked against
// libhydro's.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "libhydro/signal/welch.hpp"
#include "libhydro/waves/wave_spectrum.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/wire_in_a_sea.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;
const double kPi = std::acos(-1.0);

CliRun plot(const std::string& args) { return flexmoor("plot " + args); }

// 8 x 4.8 in at 130 dpi (the spectrum and study figures), 9 x 5.5 in (shapes), 8 x 5 in
// (extremes): matplotlib rounds to whole pixels.
void expectPng(const fs::path& png, uint32_t width, uint32_t height) {
  const auto [w, h] = pngSize(png);
  EXPECT_EQ(w, width) << png;
  EXPECT_EQ(h, height) << png;
}

void expectRefused(const CliRun& r, const std::string& message) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.errors.find("flexmoor plot: " + message), std::string::npos) << r.errors;
}

TEST(PlotFigures, SpectrumOfASeriesAgainstTheTargetOfItsSea) {
  const fs::path nc = runWireInASea("plot-spectrum", 800);
  const fs::path dir = nc.parent_path();
  const CliRun elevation = plot(nc.string() + " -o " + (dir / "sea.png").string() +
                                " --spectrum wave_elevation --segment 50");
  ASSERT_EQ(elevation.exit_code, 0) << elevation.output;
  // The dynamic step's first state and 800 records of 0.25 s (evenly spaced: no step was cut),
  // segments of 200 samples overlapping by half: 7 of them.
  EXPECT_NE(elevation.output.find("spectrum of 801 samples, 7 segments"), std::string::npos)
      << elevation.output;
  EXPECT_EQ(elevation.errors.find("interpolated"), std::string::npos) << elevation.errors;
  expectPng(dir / "sea.png", 1040, 624);
  const CliRun tension = plot(nc.string() + " -o " + (dir / "tension.png").string() +
                              " --spectrum tension_end@element=1,end=1 --from 100");
  ASSERT_EQ(tension.exit_code, 0) << tension.output;
  expectPng(dir / "tension.png", 1040, 624);
}

// The plot's target spectrum and Welch estimate against libhydro's (the plot restates both in
// numpy): JONSWAP (Hs 2 m, Tp 8 s, gamma 3.3) and Pierson-Moskowitz (Hs 5 m, Tp 12 s) at 7
// frequencies from 0.4 to 3 wp, and Welch (64-sample segments, dt 0.1 s) of x_j = sin(0.7 j^2 +
// 0.3) + 0.1 j, j < 300, at every bin. Reference: WaveSpectrum::density and signal::welch.
// Measured: 2.9e-15 relative (spectra: the same Simpson sums in another order), 1.8e-12 (Welch,
// at its smallest bins, where numpy's sin of arguments up to 6e4 and its FFT differ from glibc's
// and FFTW's in the last bits). Tolerances 1e-14 and 3e-12.
TEST(PlotFigures, TargetSpectrumAndWelchAreLibhydros) {
  const std::string script = "import sys; sys.path.insert(0, '" FLEXMOOR_SOURCE_DIR
                             "/apps/plot'); "
                             "import numpy as np, flexmoor_plot as p; "
                             "f = np.array([0.4, 0.8, 0.95, 1.0, 1.1, 1.6, 3.0]); "
                             "print(*p.jonswap_density(f * 2 * np.pi / 8, 2.0, 8.0, 3.3)); "
                             "print(*p.jonswap_density(f * 2 * np.pi / 12, 5.0, 12.0, 1.0)); "
                             "j = np.arange(300); "
                             "print(*p.welch(np.sin(0.7 * j**2 + 0.3) + 0.1 * j, 0.1, 64)[1])";
  const CliRun r = command("/usr/bin/python3 -c \"" + script + "\"");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream lines(r.output);
  const auto values = [&] {
    std::string line;
    std::getline(lines, line);
    std::istringstream in(line);
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
  };
  const std::vector<double> f = {0.4, 0.8, 0.95, 1.0, 1.1, 1.6, 3.0};
  const hydro::WaveSpectrum jonswap = hydro::WaveSpectrum::jonswap(2.0, 8.0, 3.3),
                            pm = hydro::WaveSpectrum::piersonMoskowitz(5.0, 12.0);
  const std::vector<double> python_jonswap = values(), python_pm = values();
  ASSERT_EQ(python_jonswap.size(), f.size());
  ASSERT_EQ(python_pm.size(), f.size());
  for (size_t k = 0; k < f.size(); ++k) {
    const double a = jonswap.density(f[k] * 2.0 * kPi / 8.0);
    const double b = pm.density(f[k] * 2.0 * kPi / 12.0);
    EXPECT_NEAR(python_jonswap[k] / a, 1.0, 1e-14) << f[k];
    EXPECT_NEAR(python_pm[k] / b, 1.0, 1e-14) << f[k];
  }
  std::vector<double> x;
  for (int j = 0; j < 300; ++j) x.push_back(std::sin(0.7 * j * j + 0.3) + 0.1 * j);
  const signal::SpectralEstimate e = signal::welch(x, 0.1, 64);
  const std::vector<double> python_welch = values();
  ASSERT_EQ(python_welch.size(), e.density.size());
  for (size_t k = 0; k < e.density.size(); ++k)
    EXPECT_NEAR(python_welch[k] / e.density[k], 1.0, 3e-12) << k;
}

TEST(PlotFigures, LineShapesAtChosenTimes) {
  const fs::path nc = runWireInASea("plot-shapes", 200);
  const fs::path png = nc.parent_path() / "shapes.png";
  const CliRun r = plot(nc.string() + " -o " + png.string() + " --shapes 0,10,20,50");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("4 shapes"), std::string::npos) << r.output;
  expectPng(png, 1170, 715);
}

TEST(PlotFigures, ShapesAtTimesNotRecordedOrInAnUnknownPlaneAreRefused) {
  const fs::path nc = runWireInASea("plot-shapes-bad", 200);
  const fs::path png = nc.parent_path() / "shapes.png";
  expectRefused(plot(nc.string() + " -o " + png.string() + " --shapes 0,80"),
                "--shapes: the time 80 s is outside the records (0 to 50 s)");
  expectRefused(plot(nc.string() + " -o " + png.string() + " --shapes 10 --plane xx"),
                "--plane xx: expected two of x, y, z");
}

// A study.nc in the format of the contract between `flexmoor study` and `flexmoor plot`: a
// `member` dimension, the varied parameters as double variables over it (flexmoor_path, units,
// long_name; listed in study_parameters), status (member 9 failed, its statistics _FillValue),
// statistics NAME_S(member) and a response spectrum NAME_psd(member, frequency).
struct Parameter {
  std::string name, path, units;
  std::vector<double> values;
};
struct Statistic {
  std::string name, units;
  std::vector<double> values;
};

void check(int status) { ASSERT_EQ(status, NC_NOERR) << nc_strerror(status); }

void putText(int file, int variable, const std::string& name, const std::string& value) {
  check(nc_put_att_text(file, variable, name.c_str(), value.size(), value.c_str()));
}

void writeStudy(const fs::path& path, const std::vector<Parameter>& parameters,
                const std::vector<Statistic>& statistics, const std::vector<int>& status,
                const std::string& psd_name, const std::vector<std::vector<double>>& psd) {
  int file = -1, member = -1, frequency = -1, id = -1;
  const size_t members = status.size(), frequencies = psd.empty() ? 0 : psd[0].size();
  check(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &file));
  check(nc_def_dim(file, "member", members, &member));
  std::string names;
  for (const Parameter& p : parameters) names += (names.empty() ? "" : " ") + p.name;
  putText(file, NC_GLOBAL, "Conventions", "CF-1.8");
  putText(file, NC_GLOBAL, "title", "a study written by the plot's test");
  putText(file, NC_GLOBAL, "study_parameters", names);
  putText(file, NC_GLOBAL, "collect", "tension heave");
  check(nc_def_var(file, "member", NC_INT, 1, &member, &id));
  putText(file, id, "long_name", "study member");
  std::vector<int> numbers;
  for (size_t m = 0; m < members; ++m) numbers.push_back(static_cast<int>(m) + 1);
  check(nc_put_var_int(file, id, numbers.data()));
  check(nc_def_var(file, "status", NC_INT, 1, &member, &id));
  const int flags[4] = {0, 2, 3, 4};
  check(nc_put_att_int(file, id, "flag_values", NC_INT, 4, flags));
  putText(file, id, "flag_meanings", "complete bad_input not_converged failed");
  check(nc_put_var_int(file, id, status.data()));
  for (const Parameter& p : parameters) {
    check(nc_def_var(file, p.name.c_str(), NC_DOUBLE, 1, &member, &id));
    putText(file, id, "flexmoor_path", p.path);
    putText(file, id, "long_name", p.path);
    if (!p.units.empty()) putText(file, id, "units", p.units);
    check(nc_put_var_double(file, id, p.values.data()));
  }
  for (const Statistic& s : statistics) {
    check(nc_def_var(file, s.name.c_str(), NC_DOUBLE, 1, &member, &id));
    const double fill = NC_FILL_DOUBLE;
    check(nc_def_var_fill(file, id, 0, &fill));
    putText(file, id, "units", s.units);
    putText(file, id, "long_name", s.name);
    if (s.name.size() > 4 && s.name.compare(s.name.size() - 4, 4, "_mpm") == 0) {
      const double duration = 10800.0;
      check(nc_put_att_double(file, id, "mpm_duration", NC_DOUBLE, 1, &duration));
      putText(file, id, "mpm_fit", "weibull");
    }
    std::vector<double> values = s.values;
    for (size_t m = 0; m < members; ++m)
      if (status[m] != 0) values[m] = fill;
    check(nc_put_var_double(file, id, values.data()));
  }
  if (frequencies > 0) {
    check(nc_def_dim(file, "frequency", frequencies, &frequency));
    check(nc_def_var(file, "frequency", NC_DOUBLE, 1, &frequency, &id));
    putText(file, id, "units", "rad s-1");
    putText(file, id, "standard_name", "angular_frequency");
    putText(file, id, "long_name", "circular frequency");
    std::vector<double> omega;
    for (size_t k = 0; k < frequencies; ++k) omega.push_back(0.02 * static_cast<double>(k));
    check(nc_put_var_double(file, id, omega.data()));
    const int dims[2] = {member, frequency};
    check(nc_def_var(file, (psd_name + "_psd").c_str(), NC_DOUBLE, 2, dims, &id));
    putText(file, id, "units", "N2 s rad-1");
    putText(file, id, "long_name", "response spectrum of " + psd_name);
    std::vector<double> flat;
    for (const auto& row : psd) flat.insert(flat.end(), row.begin(), row.end());
    check(nc_put_var_double(file, id, flat.data()));
  }
  check(nc_close(file));
}

// 3 sea states x 3 seeds (the shape of the OC4 study), member 9 failed; the tension's maximum
// and MPM grow with Hs, differ by seed; a Gaussian response spectrum per member.
fs::path writeSeaStateStudy(const std::string& name) {
  const fs::path dir = scratch(name);
  std::vector<double> hs, seed, max, mpm;
  std::vector<std::vector<double>> psd;
  for (double h : {2.0, 4.0, 6.0})
    for (double s : {1.0, 2.0, 3.0}) {
      hs.push_back(h);
      seed.push_back(s);
      max.push_back(1.0e6 + 1.5e5 * h + 2.0e4 * s);
      mpm.push_back(1.0e6 + 1.6e5 * h + 1.0e4 * s);
      std::vector<double> row;
      for (int k = 0; k < 100; ++k)
        row.push_back(1.0e9 * h * h * std::exp(-std::pow((0.02 * k - 0.7) / 0.15, 2)));
      psd.push_back(row);
    }
  writeStudy(dir / "study.nc",
             {{"waves_spectrum_Hs", "waves.spectrum.Hs", "m", hs},
              {"waves_spectrum_seed", "waves.spectrum.seed", "", seed}},
             {{"tension_max", "N", max}, {"tension_mpm", "N", mpm}}, {0, 0, 0, 0, 0, 0, 0, 0, 4},
             "tension", psd);
  return dir / "study.nc";
}

TEST(PlotFigures, ExtremesAgainstHsOfAStudy) {
  const fs::path nc = writeSeaStateStudy("plot-extremes");
  const fs::path png = nc.parent_path() / "extremes.png";
  const CliRun r = plot(nc.string() + " -o " + png.string() +
                        " --extremes tension --against waves_spectrum_Hs"
                        " --group waves_spectrum_seed");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("extremes of 8 members"), std::string::npos) << r.output;
  expectPng(png, 1040, 650);
}

TEST(PlotFigures, ResponseSpectraOfAStudy) {
  const fs::path nc = writeSeaStateStudy("plot-psd");
  const fs::path png = nc.parent_path() / "psd.png";
  const CliRun r = plot(nc.string() + " -o " + png.string() + " --psd tension");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("8 response spectra"), std::string::npos) << r.output;
  expectPng(png, 1040, 624);
}

// A regular-wave study (like tube-rao: periods 4-12 s, height 2 m): heave amplitude
// against the period, as an RAO with the height a parameter.
TEST(PlotFigures, ResponseAmplitudeCurveOfARegularWaveStudy) {
  const fs::path dir = scratch("plot-rao");
  std::vector<double> period, height, heave;
  for (double t = 4.0; t <= 12.0; t += 1.0) {
    period.push_back(t);
    height.push_back(2.0);
    heave.push_back(1.0 / std::sqrt(std::pow(1.0 - std::pow(8.0 / t, 2), 2) + 0.09));
  }
  writeStudy(dir / "study.nc",
             {{"waves_components_0_period", "waves.components.0.period", "s", period},
              {"waves_components_0_height", "waves.components.0.height", "m", height}},
             {{"heave_amplitude", "m", heave}}, std::vector<int>(period.size(), 0), "", {});
  const fs::path png = dir / "rao.png";
  const CliRun r = plot((dir / "study.nc").string() + " -o " + png.string() +
                        " --rao heave --against waves_components_0_period"
                        " --wave-height waves_components_0_height");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("response-amplitude curve of 9 members"), std::string::npos) << r.output;
  expectPng(png, 1040, 624);
  expectRefused(plot((dir / "study.nc").string() + " -o " + png.string() +
                     " --rao heave --against waves_components_0_period --wave-height tall"),
                "--wave-height tall: expected a height (a number, in the study's length unit) "
                "or a parameter (the study's: waves_components_0_period, "
                "waves_components_0_height)");
}

TEST(PlotFigures, StudyFigureWithoutOrWithAnUnknownParameterIsRefused) {
  const fs::path nc = writeSeaStateStudy("plot-study-parameter");
  const std::string to = nc.string() + " -o " + (nc.parent_path() / "x.png").string();
  expectRefused(plot(to + " --extremes tension"),
                "--extremes needs --against PARAMETER (the study's: waves_spectrum_Hs, "
                "waves_spectrum_seed)");
  expectRefused(plot(to + " --extremes tension --against waves.Hs"),
                "no parameter 'waves.Hs' in the study (its parameters: waves_spectrum_Hs, "
                "waves_spectrum_seed)");
  EXPECT_FALSE(fs::exists(nc.parent_path() / "x.png"));
}

TEST(PlotFigures, StatisticNotCollectedOrARunFigureOfAStudyIsRefused) {
  const fs::path nc = writeSeaStateStudy("plot-study-statistic");
  const std::string to = nc.string() + " -o " + (nc.parent_path() / "x.png").string();
  expectRefused(plot(to + " --rao tension --against waves_spectrum_Hs"),
                "no variable 'tension_amplitude' in the study (collected: tension heave;");
  expectRefused(plot(to + " --series position_x@node=1"),
                nc.string() +
                    " is a study (a 'member' dimension): it takes --rao, --extremes "
                    "or --psd");
  EXPECT_FALSE(fs::exists(nc.parent_path() / "x.png"));
}

TEST(PlotFigures, StudyFigureOfARunOrAnotherFiguresOptionIsRefused) {
  const fs::path nc = runWireInASea("plot-run-kind", 20);
  const std::string to = nc.string() + " -o " + (nc.parent_path() / "x.png").string();
  expectRefused(plot(to + " --psd tension"), "--psd draws a study's DIR/study.nc; " + nc.string() +
                                                 " has no 'member' dimension");
  expectRefused(plot(to + " --shapes 10 --segment 100"),
                "--segment is an option of --spectrum, not of --shapes");
  EXPECT_FALSE(fs::exists(nc.parent_path() / "x.png"));
}

TEST(PlotFigures, SpectrumOfTooShortASegmentOrAnUnknownElementIsRefused) {
  const fs::path nc = runWireInASea("plot-spectrum-bad", 20);
  const std::string to = nc.string() + " -o " + (nc.parent_path() / "x.png").string();
  expectRefused(plot(to + " --spectrum wave_elevation --segment 1"),
                "--segment 1: expected at least 8 samples");
  expectRefused(plot(to + " --spectrum tension_end@element=9,end=1"),
                "element=9 in tension_end: no such element in the file (it has 1 to 4)");
  EXPECT_FALSE(fs::exists(nc.parent_path() / "x.png"));
}

}  // namespace
}  // namespace flexmoor::test
