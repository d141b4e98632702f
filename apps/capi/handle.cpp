#include "apps/capi/handle.hpp"

#include <cstdint>
#include <mutex>
#include <unordered_map>

namespace flexmoor::capi {
namespace {

const char kUnknownHandle[] =
    "flexmoor: a null, closed or unknown handle (flexmoor_create makes one, flexmoor_close ends "
    "it)";

// The open handles. A handle is a number, never reused, that this table maps to its simulation:
// a call with a closed or made-up handle finds nothing and says so, instead of touching freed
// memory.
class Registry {
 public:
  flexmoor_t add(std::unique_ptr<flexmoor_simulation> s) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const uintptr_t id = next_++;
    open_.emplace(id, std::move(s));
    return reinterpret_cast<flexmoor_t>(id);
  }
  flexmoor_simulation* find(flexmoor_t h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = open_.find(reinterpret_cast<uintptr_t>(h));
    return found == open_.end() ? nullptr : found->second.get();
  }
  std::unique_ptr<flexmoor_simulation> remove(flexmoor_t h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = open_.find(reinterpret_cast<uintptr_t>(h));
    if (found == open_.end()) return nullptr;
    std::unique_ptr<flexmoor_simulation> s = std::move(found->second);
    open_.erase(found);
    return s;
  }

 private:
  std::mutex mutex_;
  std::unordered_map<uintptr_t, std::unique_ptr<flexmoor_simulation>> open_;
  uintptr_t next_ = 1;
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

flexmoor_simulation* findHandle(flexmoor_t handle) { return registry().find(handle); }
flexmoor_t addHandle(std::unique_ptr<flexmoor_simulation> s) {
  return registry().add(std::move(s));
}
std::unique_ptr<flexmoor_simulation> removeHandle(flexmoor_t handle) {
  return registry().remove(handle);
}

void require(bool condition, const std::string& what) {
  if (!condition) throw BadCall(what);
}

void requirePhase(const flexmoor_simulation& h, flexmoor_simulation::Phase phase,
                  const char* call) {
  using Phase = flexmoor_simulation::Phase;
  if (h.phase == phase) return;
  const char* now = h.phase == Phase::Created    ? "before flexmoor_init"
                    : h.phase == Phase::Stepping ? "after flexmoor_init"
                    : h.phase == Phase::Finished ? "after flexmoor_finish"
                                                 : "after a failure that ended the simulation";
  const char* needed = phase == Phase::Created    ? "before flexmoor_init"
                       : phase == Phase::Stepping ? "between flexmoor_init and flexmoor_finish"
                                                  : "after flexmoor_finish";
  throw BadCall(std::string(call) + ": called " + now + " (it is for " + needed + ")");
}

const app::CaseLine& lineAt(const flexmoor_simulation& h, int line, const char* call) {
  require(line >= 0 && line < static_cast<int>(h.lines.size()),
          std::string(call) + ": line " + std::to_string(line) + " out of range (the case has " +
              std::to_string(h.lines.size()) + " lines, 0 to " +
              std::to_string(static_cast<int>(h.lines.size()) - 1) + ")");
  return *h.lines[line];
}

int lineNode(const flexmoor_simulation& h, int line, int node, const char* call) {
  const app::CaseLine& l = lineAt(h, line, call);
  require(node >= 0 && node < static_cast<int>(l.nodes.size()),
          std::string(call) + ": node " + std::to_string(node) + " out of range (line " + l.name +
              " has " + std::to_string(l.nodes.size()) + " nodes)");
  return l.nodes[node];
}

void requireState(const flexmoor_simulation& h, const char* call) {
  require(h.phase == flexmoor_simulation::Phase::Stepping ||
              h.phase == flexmoor_simulation::Phase::Finished,
          std::string(call) + ": no state before flexmoor_init");
}

void requireCount(const flexmoor_simulation& h, int count, const char* call) {
  int dofs = 0;
  for (int n : h.coupled_dofs) dofs += n;
  require(count == dofs, std::string(call) + ": " + std::to_string(count) +
                             " coupled values (expected " + std::to_string(dofs) +
                             ": 6 for each coupled body, 3 for each coupled point)");
}

}  // namespace flexmoor::capi

using namespace flexmoor;

extern "C" {

const char* flexmoor_version(void) { return FLEXMOOR_VERSION; }

void flexmoor_close(flexmoor_t handle) {
  try {
    // The run's records so far stay in its .partial file; nothing is put in place.
    capi::removeHandle(handle);
  } catch (...) {
  }
}

const char* flexmoor_last_error(flexmoor_t handle) {
  const flexmoor_simulation* h = capi::findHandle(handle);
  return h ? h->error.c_str() : capi::kUnknownHandle;
}

}  // extern "C"
