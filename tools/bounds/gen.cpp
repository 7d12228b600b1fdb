// polarcade-bounds gen: bounds from a sprite's alpha channel (the algorithm is polar::generateBounds in
// the engine core; this file reads the PNG, prints, and writes the file atomically).
#include <unistd.h>

#include <cstdio>
#include <string_view>

#include "bounds_tool.h"
#include "cli.h"
#include "polar/authoring/bounds_gen.h"
#include "polar/image_extensions.h"
#include "polar/platform/image_file.h"

namespace polar::bounds_tool {
namespace {

std::string fixed(double v, int decimals = 2) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

int fail(const Error& error) {
    std::fprintf(stderr, "%s\n", error.message().c_str());
    return cli::kBadInput;
}

}  // namespace

std::string defaultBoundsPath(const std::string& sprite) {
    const std::string_view stem = withoutImageExtension(sprite);
    return (stem.empty() ? sprite : std::string(stem)) + ".bounds.json";
}

std::string qualityLine(std::size_t k, const BoundSpec& bound, const FitQuality& quality, bool container,
                        int imagePixels) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "radii %zu: centre (%s, %s), %zu samples, %d %s pixels; worst slack %s px at %s deg, "
                  "mean slack %s px, worst miss %s px",
                  k + 1, fixed(bound.centre.x()).c_str(), fixed(bound.centre.y()).c_str(),
                  bound.samples.size(), container ? imagePixels - quality.pixels : quality.pixels,
                  container ? "free" : "opaque", fixed(quality.worstSlack).c_str(),
                  fixed(quality.worstSlackDegrees).c_str(), fixed(quality.meanSlack).c_str(),
                  fixed(quality.worstMiss, 3).c_str());
    return line;
}

// "X,Y": two finite decimal numbers (the one rule for numbers on the command line, cli/numbers.h).
std::optional<Vec2> parsePoint(const std::string& text) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    const cli::Range<double> finite;
    std::string problem;
    const std::optional<double> x =
        cli::parseNumber(std::string_view(text).substr(0, comma), finite, problem);
    const std::optional<double> y =
        cli::parseNumber(std::string_view(text).substr(comma + 1), finite, problem);
    if (!x || !y) return std::nullopt;
    return Vec2(*x, *y);
}

void addGen(cli::Command& app, GenArgs& args) {
    app.footer(
        "Generate bounds from a sprite's alpha channel. A pixel is opaque when its alpha is above the "
        "threshold "
        "(default 127), and counts as its full square. The outline (straight edges, \"interpolate\": true) "
        "encloses every opaque pixel square with the least area; it is reported with its worst and mean "
        "slack "
        "(outline radius minus the farthest opaque point, along rays from the centre, over 7200 directions) "
        "and "
        "its worst miss (how far any opaque square pokes out; 0 means fully enclosed). With --container the "
        "outline instead stays inside the free space around the centre, as large as it can; slack is then "
        "the "
        "free space left before the wall. Gaps between samples stay at most 150 degrees. Bound space: one "
        "unit per "
        "sprite pixel, origin at the sprite's centre, x right, y up, angles in degrees counter-clockwise "
        "from +x.");
    app.option("sprite", args.sprite,
               "Sprite image (PNG, or any format polarcade reads: GIF, WebP, TGA, BMP and more)")
        .required();
    app.option("-n,--samples", args.samples,
               "Samples per radii (3..720); default: one per 6 px of outline, 8..64 (containers up to 192)",
               {0, 720});
    app.option("--centre", args.centre,
               "Centre X,Y in bound space (sprite pixels, origin at the sprite's centre, y up); default: the "
               "centroid of the opaque pixels, or 0,0 for --container")
        .typeName("X,Y")
        .check([](const std::string& text) {
            return parsePoint(text) ? std::string()
                                    : "expected X,Y with two finite numbers, e.g. 1.5,-2, got " +
                                          (text.empty() ? std::string("nothing") : text);
        });
    app.option("--radii", args.radii,
               "Split the sprite along its principal axis into K parts, one Bound each (1..16)", {1, 16});
    app.flag("--container", args.container,
             "Bounds for a container: the outline lies inside the free space around the centre");
    app.option("--threshold", args.threshold, "Alpha above which a pixel is opaque (0..254)", {0, 254});
    app.option("-o,--output", args.output, "Where to write; default: NAME.bounds.json beside the sprite");
    app.flag("-q,--quiet", args.quiet, "Print only errors and the file written");
}

int runGen(const GenArgs& args) {
    BoundsGenOptions options;
    options.samples = args.samples;
    options.radii = args.radii;
    options.container = args.container;
    options.threshold = static_cast<std::uint8_t>(args.threshold);
    if (!args.centre.empty()) options.centre = parsePoint(args.centre);  // checked as it was read
    Result<RgbaImage> image = loadRgbaImage(args.sprite);
    if (!image) return fail(image.error());

    const bool showProgress = !args.quiet && ::isatty(::fileno(stderr));
    if (showProgress)
        options.progress = [](const std::string& stage, double fraction) {
            std::fprintf(stderr, "\rgen: %-12s %3d%%", stage.c_str(),
                         static_cast<int>(fraction * 100.0 + 0.5));
            std::fflush(stderr);
        };
    Result<GeneratedBounds> generated = generateBounds(alphaMaskOf(*image), options);
    if (showProgress) std::fprintf(stderr, "\r%30s\r", "");
    if (!generated) {
        Error error = generated.error();
        error.file = args.sprite;
        return fail(error);
    }

    if (!args.quiet) {
        const GeneratedBounds& g = *generated;
        std::printf("%s: %dx%d, threshold %d, %s\n", args.sprite.c_str(), image->width, image->height,
                    args.threshold,
                    args.container ? "container (outline inside the free space)" : "enclosing");
        for (std::size_t k = 0; k < g.spec.radii.size(); ++k)
            std::printf("  %s\n", qualityLine(k, g.spec.radii[k], g.quality[k], args.container,
                                              image->width * image->height)
                                      .c_str());
    }
    std::string output = args.output.empty() ? defaultBoundsPath(args.sprite) : args.output;
    if (std::optional<Error> error = saveBounds(output, generated->spec)) return fail(*error);
    std::printf("wrote %s\n", output.c_str());
    for (const FitQuality& q : generated->quality)
        if (q.worstMiss > 0.0) {
            std::fprintf(stderr, "%s: the outline misses by %s px; expected 0 (please report this sprite)\n",
                         args.sprite.c_str(), fixed(q.worstMiss, 3).c_str());
            return 1;
        }
    return 0;
}

}  // namespace polar::bounds_tool
