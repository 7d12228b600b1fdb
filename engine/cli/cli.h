#pragma once
// Shared command-line handling for Polarcade's executables: CLI11 parsing where a bad flag gets one
// line naming the problem and exit code 2, --help exits 0, and --version prints the project's version.
#include <CLI/CLI.hpp>
#include <cctype>
#include <cstdio>
#include <string>

#include "polarcade_version.h"

namespace polar::cli {

inline constexpr int kBadInput = 2;

// Whether `app` or any of its subcommands, at any depth, has the option `name` ("--scale", "-j").
inline bool knowsOption(CLI::App& app, const std::string& name) {
    if (app.get_option_no_throw(name)) return true;
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        if (knowsOption(*sub, name)) return true;
    return false;
}

// The first argument that looks like an option nothing in `app` has, or "". CLI11 reports a missing
// required argument before an unknown flag, which would blame the wrong thing ("sprite is required"
// for "gen --sprit x.png"); the unknown flag is the real mistake.
inline std::string unknownOption(CLI::App& app, int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") break;
        if (arg.size() < 2 || arg[0] != '-') continue;
        if (std::isdigit(static_cast<unsigned char>(arg[1])) || arg[1] == '.') continue;  // a negative number
        const std::string name = arg[1] == '-' ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
        if (!knowsOption(app, name)) return name;
    }
    return "";
}

// Gives `app` a --version flag that prints "NAME VERSION" (the project's version) and exits 0.
inline void addVersionFlag(CLI::App& app) {
    if (app.get_option_no_throw("--version")) return;
    app.set_version_flag("--version", app.get_name() + " " + kPolarcadeVersion, "Print the version and exit");
}

// Parses argv into `app`, with --version added. Returns -1 to go on, otherwise the exit code to
// return at once.
inline int parse(CLI::App& app, int argc, char** argv) {
    addVersionFlag(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string unknown = unknownOption(app, argc, argv);
        if (!unknown.empty())
            std::fprintf(stderr, "%s: unknown option %s; see %s --help\n", app.get_name().c_str(),
                         unknown.c_str(), app.get_name().c_str());
        else
            std::fprintf(stderr, "%s: %s; see %s --help\n", app.get_name().c_str(), e.what(),
                         app.get_name().c_str());
        return kBadInput;
    }
    return -1;
}

}  // namespace polar::cli
