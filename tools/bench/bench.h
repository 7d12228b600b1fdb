#pragma once
// polarcade-bench: each benchmark is a subcommand in a file of its own (bench_<name>.cpp) that
// registers itself here. Benchmarks print a table and, with --csv, write CSV; they are programs,
// never timed unit tests.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace polar::bench {

struct Command {
    std::string name;
    std::string description;
    // Adds the subcommand's options to `sub` and returns what runs it (exit code).
    std::function<std::function<int()>(CLI::App& sub)> setup;
};

std::vector<Command>& registry();

struct Registrar {
    explicit Registrar(Command command) { registry().push_back(std::move(command)); }
};

}  // namespace polar::bench
