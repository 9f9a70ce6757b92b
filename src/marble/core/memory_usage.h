#pragma once
// How much memory this process holds, as the operating system counts it (Linux /proc).
// For benchmarks and diagnostics: the numbers are what `top` shows, not what we allocated.
#include <cstddef>

namespace marble {

// Resident set size now, in bytes (/proc/self/statm); 0 when it cannot be read.
size_t residentBytes();

// Largest resident set size so far, in bytes (getrusage); 0 when it cannot be read.
size_t peakResidentBytes();

}  // namespace marble
