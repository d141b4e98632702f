// Simulation::saveFile and restoreFile: a checkpoint in a binary file of the machine's doubles
// and ints, headed by a magic line and the case's name and size, which a restore checks.
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/run/simulation_checkpoint.hpp"

namespace flexmoor::app {
namespace {

const char kMagic[] = "flexmoor checkpoint 1\n";

class Writer {
 public:
  explicit Writer(const std::string& path) : out_(path, std::ios::binary | std::ios::trunc) {
    if (!out_) throw std::runtime_error(path + ": cannot write the checkpoint");
  }
  void bytes(const void* p, size_t n) { out_.write(static_cast<const char*>(p), n); }
  void number(double x) { bytes(&x, sizeof x); }
  void count(int64_t n) { bytes(&n, sizeof n); }
  void text(const std::string& s) {
    count(static_cast<int64_t>(s.size()));
    bytes(s.data(), s.size());
  }
  void numbers(const std::vector<double>& v) {
    count(static_cast<int64_t>(v.size()));
    bytes(v.data(), sizeof(double) * v.size());
  }
  void field(const model::NodalField& f) { bytes(f.data(), sizeof(double) * f.size()); }
  void state(const model::State& s) {
    count(s.displacement.cols());  // 0 for a state not set (an interpolator's, fixed steps)
    field(s.displacement);
    field(s.velocity);
    field(s.acceleration);
    number(s.time);
    number(s.load_factor);
    count(s.still);
    const model::MotionRecord& m = s.motion;
    count(m.valid);
    count(m.mass_kind);
    for (double x :
         {m.load_factor, m.rayleigh_mass, m.rayleigh_stiffness, m.hht_alpha, m.force_scale})
      number(x);
  }
  void close(const std::string& path) {
    out_.close();
    if (!out_) throw std::runtime_error(path + ": cannot write the checkpoint");
  }

 private:
  std::ofstream out_;
};

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw std::runtime_error(path + ": cannot read the checkpoint");
  }
  void bytes(void* p, size_t n) {
    in_.read(static_cast<char*>(p), n);
    if (!in_) fail("it ends early");
  }
  double number() {
    double x;
    bytes(&x, sizeof x);
    return x;
  }
  int64_t count(int64_t most) {
    int64_t n;
    bytes(&n, sizeof n);
    if (n < 0 || n > most) fail("a count of " + std::to_string(n) + " is out of range");
    return n;
  }
  std::string text() {
    std::string s(count(1 << 20), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  std::vector<double> numbers() {
    std::vector<double> v(count(int64_t(1) << 32));
    bytes(v.data(), sizeof(double) * v.size());
    return v;
  }
  void field(model::NodalField& f) { bytes(f.data(), sizeof(double) * f.size()); }
  model::State state(int nodes) {
    const int64_t columns = count(nodes);
    if (columns != 0 && columns != nodes) fail("a state of another model");
    model::State s(static_cast<int>(columns));
    field(s.displacement);
    field(s.velocity);
    field(s.acceleration);
    s.time = number();
    s.load_factor = number();
    s.still = count(1) != 0;
    model::MotionRecord& m = s.motion;
    m.valid = count(1) != 0;
    m.mass_kind = static_cast<int>(count(16));
    m.load_factor = number();
    m.rayleigh_mass = number();
    m.rayleigh_stiffness = number();
    m.hht_alpha = number();
    m.force_scale = number();
    return s;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(path_ + ": not a checkpoint this simulation can restore (" + why +
                             ")");
  }

 private:
  std::string path_;
  std::ifstream in_;
};

}  // namespace

void Simulation::saveFile(const std::string& path, const std::vector<double>& host) {
  const std::shared_ptr<const Checkpoint> cp = save();
  Writer w(path);
  w.bytes(kMagic, sizeof kMagic - 1);
  w.text(c_.name);
  w.count(c_.model->nodeCount());
  w.count(cp->step);
  w.state(cp->integrator.state);
  w.count(cp->integrator.steps_since_update);
  w.number(cp->integrator.force_scale);
  w.number(cp->integrator.next_step);
  w.count(cp->accepted);
  w.count(cp->output_index);
  w.number(cp->next_report);
  w.number(cp->last_record_time);
  w.numbers(cp->series.progress());
  w.state(cp->between.before());
  w.state(cp->between.after());
  w.numbers(host);
  w.close(path);
}

std::vector<double> Simulation::restoreFile(const std::string& path, const CheckpointHost& check) {
  if (!dynamic_) throw std::logic_error("Simulation::restoreFile: no dynamic step under way");
  Reader r(path);
  char magic[sizeof kMagic - 1];
  r.bytes(magic, sizeof magic);
  if (std::string(magic, sizeof magic) != kMagic) r.fail("no checkpoint header");
  if (r.text() != c_.name) r.fail("of another case than " + c_.name);
  const int nodes = c_.model->nodeCount();
  if (r.count(int64_t(1) << 40) != nodes) r.fail("of a model of another size");
  Checkpoint cp = *save();  // this step's series and interpolator, to be filled from the file
  if (r.count(1 << 30) != cp.step) r.fail("of another step");
  cp.integrator.state = r.state(nodes);
  cp.integrator.steps_since_update = static_cast<int>(r.count(1 << 30));
  cp.integrator.force_scale = r.number();
  cp.integrator.next_step = r.number();
  cp.accepted = static_cast<int>(r.count(int64_t(1) << 31));
  cp.output_index = static_cast<int>(r.count(int64_t(1) << 31));
  cp.next_report = r.number();
  cp.last_record_time = r.number();
  cp.series.resume(r.numbers());
  const model::State before = r.state(nodes);
  const model::State after = r.state(nodes);
  cp.between.resume(before, after);
  std::vector<double> host = r.numbers();
  if (check) check(host);
  if (cp.integrator.state.time < last_sunk_time_)
    throw std::logic_error(path + ": its time, " + std::to_string(cp.integrator.state.time) +
                           " s, is before records this run has written already (to " +
                           std::to_string(last_sunk_time_) +
                           " s); a checkpoint in memory holds its records back and can go back");
  restore(cp);
  return host;
}

}  // namespace flexmoor::app
