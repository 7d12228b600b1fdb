#include "memory.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace polar::bench {

double peakResidentMiB(pid_t pid) {
    std::ifstream status(pid ? "/proc/" + std::to_string(pid) + "/status" : "/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0.0;
}

long residentKiB() {
    const int fd = ::open("/proc/self/statm", O_RDONLY);
    if (fd < 0) return -1;
    char buffer[128];
    const ssize_t n = ::read(fd, buffer, sizeof buffer - 1);
    ::close(fd);
    if (n <= 0) return -1;
    buffer[n] = '\0';
    long size = 0, resident = 0;  // in pages: the second field
    if (std::sscanf(buffer, "%ld %ld", &size, &resident) != 2) return -1;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

}  // namespace polar::bench
