#include <algorithm>
#include <cstdio>

#include "bench.h"
#include "cli.h"

namespace polar::bench {
std::vector<Command>& registry() {
    static std::vector<Command> commands;
    return commands;
}
}  // namespace polar::bench

int main(int argc, char** argv) {
    CLI::App app{"Polarcade's benchmarks: each prints a table of medians and can write CSV.",
                 "polarcade-bench"};
    app.require_subcommand(1);
    auto& commands = polar::bench::registry();
    std::sort(commands.begin(), commands.end(), [](auto& a, auto& b) { return a.name < b.name; });
    std::vector<std::pair<CLI::App*, std::function<int()>>> runners;
    for (auto& command : commands) {
        CLI::App* sub = app.add_subcommand(command.name, command.description);
        runners.emplace_back(sub, command.setup(*sub));
    }
    if (int code = polar::cli::parse(app, argc, argv); code >= 0) return code;
    for (auto& [sub, run] : runners)
        if (sub->parsed()) return run();
    return polar::cli::kBadInput;
}
