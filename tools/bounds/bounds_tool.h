#pragma once
// polarcade-bounds: the modder's tools for sprite bound files, one subcommand per file.
#include <optional>
#include <string>
#include <vector>

#include "polar/authoring/bounds_gen.h"
#include "polar/bounds_file.h"
#include "polar/error.h"
#include "polar/math.h"

namespace polar::cli {
class Command;
}

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

struct EditArgs {
    std::string sprite;
    std::string bounds;  // empty: NAME.bounds.json beside NAME.png
    int radii = 1;       // for gen's fit when there is no file
    bool container = false;
    int threshold = 127;
    std::string script;      // headless: run these events, then exit
    std::string screenshot;  // headless: the picture after the script
};

void addGen(cli::Command& app, GenArgs& args);
void addCheck(cli::Command& app, CheckArgs& args);
void addView(cli::Command& app, ViewArgs& args);
int runGen(const GenArgs& args);
int runCheck(const CheckArgs& args);
int runView(const ViewArgs& args);
void addEdit(cli::Command& app, EditArgs& args);
int runEdit(const EditArgs& args);

// One bound's fit as gen prints it: "radii K: centre (x, y), N samples, P opaque pixels; worst slack
// … px at … deg, mean slack … px, worst miss … px" (free pixels of the image for a container).
std::string qualityLine(std::size_t k, const BoundSpec& bound, const FitQuality& quality, bool container,
                        int imagePixels);
// A warning as check prints it: "file:line:column: warning: what; expected …".
std::string warningLine(const Error& at);
// NAME.bounds.json for NAME.png (gen's default output).
std::string defaultBoundsPath(const std::string& sprite);

// "X,Y" as two finite numbers.
std::optional<Vec2> parsePoint(const std::string& text);

}  // namespace polar::bounds_tool
