#pragma once
// polarcade-bounds: the modder's tools for sprite bound files, one subcommand per file.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "polar/math.h"

namespace polar::bounds_tool {

struct GenArgs {
    std::string sprite;
    int samples = 0;
    std::string centre;  // "X,Y", empty for the default
    int radii = 1;
    bool container = false;
    int threshold = 127;
    std::string output;  // empty: beside the sprite
    bool quiet = false;
};

struct CheckArgs {
    std::vector<std::string> files;
    std::vector<std::string> mods;  // mod folders laid over assets/, as `polarcade --mod`
    std::string sprite;             // with one bounds file: the sprite to check it against
    int threshold = 127;
    bool quiet = false;
};

struct ViewArgs {
    std::string file;
    std::string sprite;  // empty: found beside the bounds file
    double scale = 1.0;
    double rotate = 0.0;  // degrees
    bool flip = false;
    double zoom = 0.0;  // canvas pixels per world unit; 0: fit the drawing
    std::string output;
    bool quiet = false;
};

void addGen(CLI::App& app, GenArgs& args);
void addCheck(CLI::App& app, CheckArgs& args);
void addView(CLI::App& app, ViewArgs& args);
int runGen(const GenArgs& args);
int runCheck(const CheckArgs& args);
int runView(const ViewArgs& args);

// "X,Y" as two finite numbers.
std::optional<Vec2> parsePoint(const std::string& text);

}  // namespace polar::bounds_tool
