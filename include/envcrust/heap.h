// Process-level setting of the C library's allocator, for the programs at the edge (the CLI,
// the benches); the library stages never call it.
#pragma once

namespace envcrust::io {

/// Serve every allocation from the heap and keep freed memory there for reuse, instead of
/// mapping each large block (a vector above 32 MB) afresh and unmapping it on release: the
/// sheet's cleaning rebuilds tables of tens of MB a dozen times, and each fresh mapping is
/// paid again in page faults (a third of the extraction's time on the bunny scan).
/// Measured on the bunny scan's reconstruction (35k points, 1.8M faces, 2 cores): 48.6 s ->
/// 29.6 s wall, 707 -> 811 MB peak. glibc only (mallopt); a no-op elsewhere.
void reuse_freed_memory();

}  // namespace envcrust::io
