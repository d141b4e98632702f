#pragma once
// The chunk shape of a netCDF-4 record variable (one whose first dimension is the unlimited
// record dimension), fit for long series: a chunk holds many records (up to kMaxRecords, about
// kChunkBytes in all) and, while one record fits in kChunkBytes, the whole of each other
// dimension. netCDF's default for such a variable is one record per chunk, so every record adds
// a chunk to every variable's index and a run of 40,000 records writes 40,000 small chunks each.
#include <cstddef>
#include <vector>

namespace flexmoor::app {

// 128 KiB: fast to write and to flush (a flush writes each variable's partly filled chunk),
// while a file of a few records (a static case) stays a couple of MiB.
constexpr size_t kChunkBytes = size_t{128} * 1024;
constexpr size_t kMaxRecords = 2048;

// Chunk lengths (records first, then one per dimension of `extents`) for a record variable
// whose other dimensions have the lengths `extents` (0 counts as 1, for a second unlimited
// dimension) and whose values take `value_bytes` each. When one record exceeds kChunkBytes, the
// outermost dimensions are split first, so a chunk is a contiguous run of values.
std::vector<size_t> recordChunks(const std::vector<size_t>& extents, size_t value_bytes);

}  // namespace flexmoor::app
