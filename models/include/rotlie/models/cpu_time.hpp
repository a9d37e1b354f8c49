#pragma once
// CPU time of the calling thread: what a method costs, independent of the other processes of a
// shared machine (wall time is not: it grows with the load).
#include <time.h>

namespace rotlie::models {

/// CPU seconds used by this thread so far.
inline double thread_cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace rotlie::models
