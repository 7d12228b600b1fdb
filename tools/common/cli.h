#pragma once
// Shared command-line handling for Polarcade's executables: CLI11 parsing where a bad flag gets one
// line naming the problem and exit code 2, and --help exits 0.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>

namespace polar::cli {

inline constexpr int kBadInput = 2;

// Parses argv into `app`. Returns -1 to go on, otherwise the exit code to return at once.
inline int parse(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "%s: %s; see %s --help\n", app.get_name().c_str(), e.what(), app.get_name().c_str());
        return kBadInput;
    }
    return -1;
}

}  // namespace polar::cli
