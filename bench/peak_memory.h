// Peak resident memory of this process between two calls (Linux), shared by the benchmarks.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace envcrust::bench {

/// The peak resident set size since the last call (or the start), in MB, read from VmHWM in
/// /proc/self/status; then resets the peak to the current size (clear_refs 5), once the
/// allocator has given its free memory back (io::reuse_freed_memory keeps it otherwise, and
/// the next peak would count what the last run left).
inline double take_peak_mb() {
  double kb = 0;
  if (FILE* f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    while (std::fgets(line, sizeof line, f))
      if (std::strncmp(line, "VmHWM:", 6) == 0) kb = std::atof(line + 6);
    std::fclose(f);
  }
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
  if (FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
    std::fputs("5", f);
    std::fclose(f);
  }
  return kb / 1024.0;
}

}  // namespace envcrust::bench
