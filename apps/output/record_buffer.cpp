#include "apps/output/record_buffer.hpp"

namespace flexmoor::app {
RecordBuffer::RecordBuffer(std::vector<size_t> extents, size_t capacity)
    : extents_(std::move(extents)), capacity_(capacity) {
  for (const size_t n : extents_) record_values_ *= n;
}

bool RecordBuffer::isRecord(const std::vector<size_t>& start,
                            const std::vector<size_t>& count) const {
  if (start.size() != extents_.size() + 1 || count.size() != start.size() || count[0] != 1 ||
      record_values_ == 0)
    return false;
  for (size_t d = 0; d < extents_.size(); ++d)
    if (start[d + 1] != 0 || count[d + 1] != extents_[d]) return false;
  return true;
}

void RecordBuffer::reserve(nc_type type) {
  bytes_.resize(capacity_ * record_values_ * valueBytes(type));
}

std::vector<size_t> RecordBuffer::start() const {
  std::vector<size_t> s(extents_.size() + 1, 0);
  s[0] = first_;
  return s;
}

std::vector<size_t> RecordBuffer::count() const {
  std::vector<size_t> c = {records_};
  c.insert(c.end(), extents_.begin(), extents_.end());
  return c;
}

}  // namespace flexmoor::app
