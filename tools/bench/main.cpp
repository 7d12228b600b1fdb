#include <algorithm>
#include <cstdio>

#include "bench.h"

namespace polar::bench {
std::vector<Command>& registry() {
    static std::vector<Command> commands;
    return commands;
}
}  // namespace polar::bench

int main(int argc, char** argv) {
    polar::cli::Command app{"Polarcade's benchmarks: each prints a table of medians and can write CSV.",
                            "polarcade-bench"};
    app.requireSubcommand();
    auto& commands = polar::bench::registry();
    std::sort(commands.begin(), commands.end(), [](auto& a, auto& b) { return a.name < b.name; });
    std::vector<std::pair<polar::cli::Command*, std::function<int()>>> runners;
    for (auto& command : commands) {
        polar::cli::Command& sub = app.subcommand(command.name, command.description);
        runners.emplace_back(&sub, command.setup(sub));
    }
    if (int code = app.parse(argc, argv); code >= 0) return code;
    for (auto& [sub, run] : runners)
        if (sub->parsed()) return run();
    return polar::cli::kBadInput;
}
