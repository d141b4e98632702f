// The irregular forms of `waves:` (apps/case/read/read_sea.cpp, build_hydro.cpp): a case's
// spectrum, discretisation, seed, heading, spreading and band make the very sea that libhydro's
// synthesise makes of them (compared to the bit); units convert (US: Hs in ft, the spectrum's
// moments in ft^2); a table of S(f) per hertz; a measured record, as a table and as a CSV file,
// reproduces its samples; ramp_up ramps; the netCDF records the seed and the repeat period.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>

#include "apps/case/case_reader.hpp"
#include "libhydro/loads/morison_line_load.hpp"
#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/wave_synthesis.hpp"
#include "tests/support/case_files.hpp"
#include "tests/support/cli_run.hpp"
#include "tests/support/submerged_wire.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

// A 10 m cable 20 m down in 100 m of water; the waves: section appended.
std::string caseWith(const std::string& waves,
                     const std::string& steps = "  - static: {name: s}\n") {
  return "units: SI\n" + test::submergedWire("0.01 m") + waves + "steps:\n" + steps;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The case's sea against synthesise() called with the same values: every component's amplitude,
// frequency, heading and phase equal to the bit (a JONSWAP of 120 frequencies in 5 directions,
// equal-energy bins, seed 31, heading 30 deg, band [0.6, 3.5]); the origin says how it was made.
TEST(CaseReaderSea, SpectrumMakesTheSeaSynthesiseMakes) {
  const Case c = readCase(test::writeCase("sea-jonswap.yaml", caseWith(R"(waves:
  spectrum: {type: jonswap, Hs: 5 m, Tp: 11 s, gamma: 2.5}
  components: 120
  discretisation: equal_energy
  seed: 31
  heading: 30 deg
  spreading: {s: 12, directions: 5}
  band: [0.6, 3.5]
  kinematics_above_mean: constant
)")));
  hydro::SynthesisOptions o;
  o.components = 120;
  o.discretisation = hydro::Discretisation::EqualEnergy;
  o.seed = 31;
  o.heading = kPi / 6.0;
  o.spreading_s = 12.0;
  o.directions = 5;
  o.omega_min_ratio = 0.6;
  o.omega_max_ratio = 3.5;
  const auto expected =
      hydro::synthesise(hydro::WaveSpectrum::jonswap(5.0, 11.0, 2.5), o, 100.0, 9.80665).components;
  ASSERT_NE(c.sea, nullptr);
  const auto& got = c.sea->components();
  ASSERT_EQ(got.size(), 600u);
  for (size_t i = 0; i < got.size(); ++i) {
    EXPECT_TRUE(sameBits(got[i].amplitude, expected[i].amplitude)) << i;
    EXPECT_TRUE(sameBits(got[i].omega, expected[i].omega)) << i;
    EXPECT_TRUE(sameBits(got[i].heading, expected[i].heading)) << i;
    EXPECT_TRUE(sameBits(got[i].phase, expected[i].phase)) << i;
  }
  ASSERT_TRUE(c.sea_origin);
  EXPECT_EQ(c.sea_origin->kind, "spectrum");
  EXPECT_EQ(c.sea_origin->discretisation, "equal_energy");
  EXPECT_EQ(c.sea_origin->seed, 31u);
  EXPECT_EQ(c.sea_origin->repeat_period, 0.0);
  EXPECT_EQ(c.sea_origin->components, 600);
}

// Units: Pierson-Moskowitz Hs 10 ft (3.048 m in this SI case), Tp 9 s, the repeat period 20 min:
// sum a^2 / 2 over the components is Hs^2 / 16 in m^2 within 1% (the band [0.5, 4] wp holds
// 99.9% of m0, the equal grid's midpoint sampling the rest); the equal grid of the 1,200 s
// repeat period states it and puts every frequency on it (1e-9).
TEST(CaseReaderSea, ConvertsUnitsAndStatesTheRepeatPeriod) {
  std::string text = caseWith(R"(waves:
  spectrum: {type: pierson_moskowitz, Hs: 10 ft, Tp: 9 s}
  discretisation: equal
  repeat_period: 20 min
)");
  const Case c = readCase(test::writeCase("sea-pm.yaml", text));
  ASSERT_TRUE(c.sea_origin);
  EXPECT_DOUBLE_EQ(c.sea_origin->repeat_period, 1200.0);
  EXPECT_EQ(c.sea_origin->discretisation, "equal");
  double m0 = 0.0;
  for (const hydro::WaveComponent& w : c.sea->components()) {
    m0 += 0.5 * w.amplitude * w.amplitude;
    const double m = w.omega * 1200.0 / (2.0 * kPi);
    EXPECT_NEAR(m, std::round(m), 1e-9 * m);
  }
  const double hs = 10.0 * 0.3048;  // the case is in SI: Hs converted to m
  EXPECT_NEAR(m0 / (hs * hs / 16.0), 1.0, 0.01);
  // 1,200 s over [0.5, 4] wp at Tp 9 s: harmonics 67 .. 533 of 2 pi / 1200.
  EXPECT_NEAR(c.sea->components().size(), 467.0, 1.0);
}

// A table of S(f) per hertz, the triangle 0 at 0.05 Hz, 4 m^2/Hz at 0.1 Hz, 0 at 0.2 Hz: m0 =
// 0.3 m^2; its band the table's, with 400 random bins sum a^2 / 2 = m0 within 0.5% (a bin's S
// at a random point of it on a piecewise-linear S).
TEST(CaseReaderSea, TableSpectrumPerHertz) {
  const Case c = readCase(test::writeCase("sea-table.yaml", caseWith(R"(waves:
  spectrum:
    type: table
    of: frequency
    table: [[0.05 Hz, 0 m^2/Hz], [0.1 Hz, 4 m^2/Hz], [0.2 Hz, 0 m^2/Hz]]
  components: 400
  seed: 5
)")));
  double m0 = 0.0;
  for (const hydro::WaveComponent& w : c.sea->components()) {
    m0 += 0.5 * w.amplitude * w.amplitude;
    EXPECT_GE(w.omega, 2.0 * kPi * 0.05);
    EXPECT_LE(w.omega, 2.0 * kPi * 0.2);
  }
  EXPECT_NEAR(m0 / 0.3, 1.0, 0.005);
}

// A measured record as a table and as a CSV file (with a header, a comment and blank lines):
// both seas give back each sample less the mean to 1e-12 of the largest |eta| at the gauge
// [5 m, 0]; the reader warns of the record's mean; the origin states its period n dt = 32 s.
TEST(CaseReaderSea, MeasuredRecordFromTableOrFile) {
  std::vector<std::pair<double, double>> samples;
  std::string table = "[";
  const auto dir = test::scratch("sea-measured");
  std::ofstream csv(dir / "gauge.csv");
  csv << "# wave gauge 1\ntime,eta\n";
  for (int j = 0; j < 64; ++j) {
    const double t = 10.0 + 0.5 * j;
    const double eta = 0.05 + 0.8 * std::cos(0.7 * t) + 0.3 * std::sin(1.9 * t + 0.4);
    samples.emplace_back(t, eta);
    char row[96];
    std::snprintf(row, sizeof row, "%s[%.17g, %.17g]", j ? ", " : "", t, eta);
    table += row;
    csv << std::setprecision(17) << t << ", " << eta << "\n" << (j == 30 ? "\n" : "");
  }
  csv.close();
  table += "]";
  double mean = 0.0, largest = 0.0;
  for (const auto& s : samples) {
    mean += s.second / 64;
    largest = std::max(largest, std::abs(s.second));
  }
  for (const std::string& source : {"table: " + table, std::string("file: gauge.csv")}) {
    const std::string path = (dir / "measured.yaml").string();
    std::ofstream(path) << caseWith("waves:\n  measured: {" + source +
                                    ", at: [5 m, 0], heading: 0 deg}\n");
    const Case c = readCase(path);
    ASSERT_TRUE(c.sea_origin) << source;
    EXPECT_EQ(c.sea_origin->kind, "measured");
    EXPECT_DOUBLE_EQ(c.sea_origin->repeat_period, 32.0);
    EXPECT_TRUE(test::anyContains(c.warnings, "still-water offset")) << test::joined(c.warnings);
    for (const auto& [t, eta] : samples)
      EXPECT_NEAR(c.sea->elevation(Eigen::Vector3d(5.0, 0.0, 0.0), t), eta - mean, 1e-12 * largest)
          << source << " t " << t;
  }
}

// ramp_up over 20 s from t = 5 s on a regular wave: still water before 5 s, half the elevation
// of the unramped sea at 15 s (to 1e-15), all of it after 25 s.
TEST(CaseReaderSea, RampUpRampsARegularWave) {
  const auto read = [](const std::string& ramp) {
    return readCase(test::writeCase(
        "sea-ramp.yaml", caseWith("waves:\n  components: [{height: 2 m, period: 8 s}]\n" + ramp)));
  };
  const Case ramped = read("  ramp_up: {duration: 20 s, start: 5 s}\n"), plain = read("");
  const Eigen::Vector3d x(1.0, 0.0, 0.0);
  EXPECT_EQ(ramped.sea->elevation(x, 4.0), 0.0);
  EXPECT_NEAR(ramped.sea->elevation(x, 15.0), 0.5 * plain.sea->elevation(x, 15.0), 1e-15);
  EXPECT_EQ(ramped.sea->elevation(x, 26.0), plain.sea->elevation(x, 26.0));
  EXPECT_EQ(plain.sea_origin->kind, "regular");
}

// A run of a spectral sea writes its seed and repeat period as netCDF global attributes.
TEST(CaseReaderSea, NetcdfRecordsTheSeedAndRepeatPeriod) {
  const auto dir = test::scratch("sea-netcdf");
  const std::string path = (dir / "sea.yaml").string();
  std::ofstream(path) << caseWith(
      R"(waves:
  spectrum: {type: jonswap, Hs: 2 m, Tp: 8 s}
  components: 50
  discretisation: equal
  seed: 77
)",
      "  - static: {name: s}\n  - dynamic: {name: d, dt: 0.05 s, steps: 4}\n");
  const auto r =
      test::flexmoor("run " + path + " -o " + (dir / "out").string() + " --no-vtk --no-figure");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int file = -1, seed = 0, components = 0;
  double period = 0.0;
  ASSERT_EQ(nc_open((dir / "out" / "sea.nc").c_str(), NC_NOWRITE, &file), NC_NOERR);
  EXPECT_EQ(nc_get_att_int(file, NC_GLOBAL, "sea_seed", &seed), NC_NOERR);
  EXPECT_EQ(nc_get_att_int(file, NC_GLOBAL, "sea_components", &components), NC_NOERR);
  EXPECT_EQ(nc_get_att_double(file, NC_GLOBAL, "sea_repeat_period", &period), NC_NOERR);
  nc_close(file);
  EXPECT_EQ(seed, 77);
  EXPECT_EQ(components, 50);
  // 50 bins over 3.5 wp: T = 2 pi 50 / (3.5 wp) = 50 Tp / 3.5.
  EXPECT_NEAR(period, 50.0 * 8.0 / 3.5, 1e-12);
}

// The run's netCDF states the target spectrum (what `flexmoor plot --spectrum` draws) and the
// incident elevation at x = y = 0: JONSWAP Hs 2 m, Tp 8 s, gamma 3.3 (the default), band
// [0.5, 4] wp as given; a table's samples as written (0.05 Hz -> 0.1 pi rad/s, S / 2 pi);
// wave_elevation at each record's time equal to the case's Sea::elevation there (reference: the
// same call; tolerance 1e-15 m absolute, the values are the same doubles).
TEST(CaseReaderSea, NetcdfStatesTheTargetSpectrumAndTheElevation) {
  const auto dir = test::scratch("sea-netcdf-spectrum");
  const auto run = [&](const std::string& name, const std::string& waves) {
    const std::string path = (dir / (name + ".yaml")).string();
    std::ofstream(path) << caseWith(
        waves, "  - static: {name: s}\n  - dynamic: {name: d, dt: 0.05 s, steps: 6}\n");
    const auto r =
        test::flexmoor("run " + path + " -o " + (dir / name).string() + " --no-vtk --no-figure");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    int file = -1;
    EXPECT_EQ(nc_open((dir / name / (name + ".nc")).c_str(), NC_NOWRITE, &file), NC_NOERR);
    return std::pair{file, readCase(path)};
  };
  const auto text = [](int file, const char* name) {
    size_t n = 0;
    EXPECT_EQ(nc_inq_attlen(file, NC_GLOBAL, name, &n), NC_NOERR) << name;
    std::string value(n, '\0');
    EXPECT_EQ(nc_get_att_text(file, NC_GLOBAL, name, value.data()), NC_NOERR) << name;
    return value;
  };
  const auto numbers = [](int file, const char* name) {
    size_t n = 0;
    EXPECT_EQ(nc_inq_attlen(file, NC_GLOBAL, name, &n), NC_NOERR) << name;
    std::vector<double> values(n);
    EXPECT_EQ(nc_get_att_double(file, NC_GLOBAL, name, values.data()), NC_NOERR) << name;
    return values;
  };
  const auto [jonswap, c] = run("jonswap", R"(waves:
  spectrum: {type: jonswap, Hs: 2 m, Tp: 8 s}
  components: 50
  discretisation: equal
  seed: 77
)");
  const double wp = 2.0 * kPi / 8.0;
  EXPECT_EQ(text(jonswap, "sea_spectrum"), "jonswap");
  EXPECT_EQ(numbers(jonswap, "sea_spectrum_Hs"), std::vector<double>{2.0});
  EXPECT_NEAR(numbers(jonswap, "sea_spectrum_Tp")[0], 8.0, 1e-14);
  EXPECT_EQ(numbers(jonswap, "sea_spectrum_gamma"), std::vector<double>{3.3});
  const std::vector<double> band = numbers(jonswap, "sea_spectrum_band");
  ASSERT_EQ(band.size(), 2u);
  EXPECT_NEAR(band[0], 0.5 * wp, 1e-15);
  EXPECT_NEAR(band[1], 4.0 * wp, 1e-15);
  int time = -1, eta = -1;
  ASSERT_EQ(nc_inq_varid(jonswap, "time", &time), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(jonswap, "wave_elevation", &eta), NC_NOERR);
  int time_dimension = -1;
  size_t records = 0;
  ASSERT_EQ(nc_inq_dimid(jonswap, "time", &time_dimension), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(jonswap, time_dimension, &records), NC_NOERR);
  ASSERT_EQ(records, 7u);  // the dynamic step's first state and its 6 steps (the static: stage)
  std::vector<double> t(records), e(records);
  ASSERT_EQ(nc_get_var_double(jonswap, time, t.data()), NC_NOERR);
  ASSERT_EQ(nc_get_var_double(jonswap, eta, e.data()), NC_NOERR);
  EXPECT_GT(std::abs(e.back()), 0.0);
  for (size_t i = 0; i < t.size(); ++i)
    EXPECT_NEAR(e[i], c.sea->elevation(Eigen::Vector3d::Zero(), t[i]), 1e-15) << t[i];
  nc_close(jonswap);

  const auto [table, unused] = run("table", R"(waves:
  spectrum:
    type: table
    of: frequency
    table: [[0.05 Hz, 0 m^2/Hz], [0.1 Hz, 4 m^2/Hz], [0.2 Hz, 0 m^2/Hz]]
  components: 50
  discretisation: equal
  seed: 77
)");
  EXPECT_EQ(text(table, "sea_spectrum"), "table");
  const std::vector<double> omega = numbers(table, "sea_spectrum_omega"),
                            density = numbers(table, "sea_spectrum_density");
  ASSERT_EQ(omega.size(), 3u);
  ASSERT_EQ(density.size(), 3u);
  EXPECT_NEAR(omega[1], 2.0 * kPi * 0.1, 1e-15);
  EXPECT_NEAR(density[1], 4.0 / (2.0 * kPi), 1e-15);
  EXPECT_NE(nc_inq_attlen(table, NC_GLOBAL, "sea_spectrum_Hs", nullptr), NC_NOERR);
  nc_close(table);
}

// The documented example syntax reads, and a time step that does not resolve the sea's shortest
// component (the band's top, 4 wp: 2.5 s at Tp 10 s) is warned of with that period.
TEST(CaseReaderSea, WarnsOfATimeStepTooLongForTheBand) {
  const Case c = readCase(test::writeCase(
      "sea-dt.yaml",
      caseWith(R"(waves:
  spectrum: {type: jonswap, Hs: 6 m, Tp: 10 s, gamma: 3.3}
  components: 200
  discretisation: equal
  seed: 7
  heading: 0 deg
  spreading: {s: 10, directions: 9}
  band: [0.5, 4.0]
  kinematics_above_mean: wheeler
)",
               "  - static: {name: s}\n  - dynamic: {name: d, dt: 0.5 s, steps: 4}\n")));
  EXPECT_EQ(c.sea->components().size(), 1800u);
  EXPECT_TRUE(test::anyContains(c.warnings, "the period 2.5 s of the sea's shortest component"))
      << test::joined(c.warnings);
}

// kinematics_reuse: 0.5 m puts held kinematics of that radius on the Morison load; on a regular
// wave over the cable 20 m down, 2 s at dt 0.05 s, the summary's end reaction and mid-span
// displacement agree with the exact run's within 1e-6 (measured 0 and 2e-16: the points move
// by micrometres within a step here; on OC4 under 200 components the tensions agree to 1.2e-8,
// docs/performance.md).
TEST(CaseReaderSea, KinematicsReuseKeepsTheRun) {
  const auto dir = test::scratch("sea-reuse");
  const std::string waves =
      "waves:\n  components: [{height: 3 m, period: 6 s}]\n  ramp_up: {duration: 1 s}\n";
  const std::string steps =
      "  - static: {name: s}\n  - dynamic: {name: d, dt: 0.05 s, steps: 40}\nsummary:\n"
      "  rx: {quantity: reaction_x, node: cable.end}\n"
      "  uz: {quantity: displacement_z, node: 3}\n";
  const Case c = readCase(
      test::writeCase("sea-reuse.yaml", caseWith(waves + "  kinematics_reuse: 0.5 m\n", steps)));
  ASSERT_EQ(c.model->lineLoads().size(), 1u);
  const auto* morison = dynamic_cast<const hydro::MorisonLineLoad*>(c.model->lineLoads()[0].get());
  ASSERT_NE(morison, nullptr);
  EXPECT_NE(morison->heldKinematics(), nullptr);
  double values[2][2];
  for (int reuse = 0; reuse < 2; ++reuse) {
    const std::string path = (dir / ("reuse" + std::to_string(reuse) + ".yaml")).string();
    std::ofstream(path) << caseWith(waves + (reuse ? "  kinematics_reuse: 0.5 m\n" : ""), steps);
    const auto r = test::flexmoor("run " + path + " -o " + (dir / std::to_string(reuse)).string() +
                                  " --no-vtk --no-figure");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string json = test::readSummary(dir / std::to_string(reuse));
    values[reuse][0] = test::summaryValue(json, "rx");
    values[reuse][1] = test::summaryValue(json, "uz");
  }
  EXPECT_NEAR(values[1][0], values[0][0], 1e-6 * std::abs(values[0][0]));
  EXPECT_NEAR(values[1][1], values[0][1], 1e-6 * std::abs(values[0][1]));
  std::printf("reuse: rx %.3g, uz %.3g relative\n", values[1][0] / values[0][0] - 1.0,
              values[1][1] / values[0][1] - 1.0);
}

}  // namespace
}  // namespace flexmoor::app
