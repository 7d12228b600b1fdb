#pragma once
// polarcade-bench: each benchmark is a subcommand in a file of its own (bench_<name>.cpp) that
// registers itself here, and measures through the harness (harness/): stopwatches on the wall
// clock and a CPU clock, repetitions after warm-ups, summaries (median, spread, best, worst), peak
// memory, one run in a child process, output paths checked as the command line is read, and CSV
// written atomically. Benchmarks print a table and, with --csv, write CSV; they are programs, never
// timed unit tests.
#include <functional>
#include <string>
#include <vector>

#include "cli.h"
#include "harness/child.h"
#include "harness/clock.h"
#include "harness/memory.h"
#include "harness/output.h"
#include "harness/repeat.h"
#include "harness/samples.h"

namespace polar::bench {

struct Command {
    std::string name;
    std::string description;
    // Adds the subcommand's options to `sub` and returns what runs it (exit code).
    std::function<std::function<int()>(cli::Command& sub)> setup;
};

std::vector<Command>& registry();

struct Registrar {
    explicit Registrar(Command command) { registry().push_back(std::move(command)); }
};

}  // namespace polar::bench
