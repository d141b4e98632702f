#include "apps/output/record_buffer.hpp"

namespace flexmoor::app {
namespace {

size_t bytesOf(nc_type type) {
  switch (type) {
    case NC_DOUBLE:
      return sizeof(double);
    case NC_INT:
      return sizeof(int);
    default:
      return sizeof(char);
  }
}

}  // namespace

RecordBuffer::RecordBuffer(std::vector<size_t> extents, size_t capacity)
    : extents_(std::move(extents)), capacity_(capacity) {
  for (const size_t n : extents_) record_values_ *= n;
}

bool RecordBuffer::accepts(const std::vector<size_t>& start, const std::vector<size_t>& count,
                           nc_type type) const {
  if (start.size() != extents_.size() + 1 || count.size() != start.size() || count[0] != 1 ||
      record_values_ == 0)
    return false;
  for (size_t d = 0; d < extents_.size(); ++d)
    if (start[d + 1] != 0 || count[d + 1] != extents_[d]) return false;
  return empty() || (type == type_ && start[0] == first_ + records_);
}

void RecordBuffer::append(const std::vector<size_t>& start, const void* values, nc_type type) {
  if (empty()) {
    first_ = start[0];
    type_ = type;
  }
  const size_t bytes = record_values_ * bytesOf(type);
  const auto* data = static_cast<const unsigned char*>(values);
  bytes_.insert(bytes_.end(), data, data + bytes);
  ++records_;
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

void RecordBuffer::clear() {
  records_ = 0;
  bytes_.clear();
}

}  // namespace flexmoor::app
