#include "apps/output/record_chunks.hpp"

#include <algorithm>

namespace flexmoor::app {

std::vector<size_t> recordChunks(const std::vector<size_t>& extents, size_t value_bytes) {
  std::vector<size_t> chunk(extents.size());
  std::transform(extents.begin(), extents.end(), chunk.begin(),
                 [](size_t n) { return std::max<size_t>(n, 1); });
  // Bytes of one index of dimension d and everything inside it, innermost first.
  std::vector<size_t> inner(chunk.size() + 1, value_bytes);
  for (size_t d = chunk.size(); d-- > 0;) inner[d] = inner[d + 1] * chunk[d];
  for (size_t d = 0; d < chunk.size() && inner[d] > kChunkBytes; ++d) {
    chunk[d] = std::max<size_t>(1, kChunkBytes / inner[d + 1]);
    if (chunk[d] > 1) break;  // the dimensions inside d stay whole and the chunk fits
  }
  size_t record_bytes = value_bytes;
  for (const size_t n : chunk) record_bytes *= n;
  chunk.insert(chunk.begin(), std::clamp<size_t>(kChunkBytes / record_bytes, 1, kMaxRecords));
  return chunk;
}

}  // namespace flexmoor::app
