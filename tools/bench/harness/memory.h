#pragma once
// Memory of a process, from /proc: the peak resident set (VmHWM) and the resident set now.
#include <sys/types.h>

namespace polar::bench {

// Peak resident memory of `pid` (0: this process) in MiB, from /proc/PID/status; 0 when unknown.
double peakResidentMiB(pid_t pid = 0);

// Resident memory of this process now in KiB (/proc/self/statm), -1 when unknown. Allocates
// nothing, so it can watch a loop for growth.
long residentKiB();

}  // namespace polar::bench
