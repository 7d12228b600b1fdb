// polarcade-bounds view: a picture of a bounds file over its sprite, drawn by the game's renderer with the
// outline the collision rule uses (polar::boundOutline, the same routine as the game's debug overlay).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bounds_drawing.h"
#include "bounds_tool.h"
#include "cli.h"
#include "polar/authoring/bounds_check.h"
#include "polar/bound_outline.h"
#include "polar/bounds_file.h"
#include "polar/platform/image_file.h"
#include "polar/render/render.h"
#include "polar/transform.h"

namespace polar::bounds_tool {
namespace {

namespace fs = std::filesystem;
using render::Color;

constexpr int kDrawingWidth = 640;
constexpr int kPanelWidth = 132;  // the key, right of the drawing
constexpr int kWidth = kDrawingWidth + kPanelWidth;
constexpr int kDrawingHeight = 512;  // below the header
constexpr double kMargin = 56;       // canvas pixels kept free around the drawing, for labels
constexpr double kMaxZoom = 40;

int fail(const Error& error) {
    std::fprintf(stderr, "%s\n", error.message().c_str());
    return cli::kBadInput;
}

std::string number(double v, int decimals = 2) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    std::string s = buffer;
    if (s.find('.') != std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

// The text, cut at the front with "..." if it is wider than `width` canvas pixels at scale 1.
std::string fitWidth(const std::string& text, int width) {
    std::size_t most = static_cast<std::size_t>(width / render::kCharAdvance);
    if (text.size() <= most) return text;
    return "..." + text.substr(text.size() - (most - 3));
}

Color dimmed(Color c, std::uint8_t alpha) {
    return c.withAlpha(alpha);
}

// Text placed so that its centre is at canvas point p.
struct Label {
    int x, y, w, h;
    bool overlaps(const Label& o) const {
        return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
    }
};

Label labelAt(const std::string& text, const Vec2& p) {
    render::TextSize size = render::measureText(text, 1);
    return {static_cast<int>(std::lround(p.x() - size.width / 2.0)), static_cast<int>(std::lround(p.y() - 4)),
            size.width, 9};
}

// The key right of the drawing: the angle convention and what each mark means.
void drawKey(render::Canvas& canvas, int top, int height) {
    const int x = kDrawingWidth + 8;
    render::fillRect(canvas, kDrawingWidth, top, kPanelWidth, height, Color{16, 17, 26, 255});
    render::drawText(canvas, "ANGLES", x, top + 10, 1, kText);
    drawCompass(canvas, Vec2(kDrawingWidth + kPanelWidth / 2.0, top + 76));
    int y = top + 124;
    for (const char* line : {"degrees, counter-", "clockwise from +x", "(x right, y up)"}) {
        render::drawText(canvas, line, x, y, 1, kDimText);
        y += render::kLineHeight;
    }
    y += 14;
    render::drawText(canvas, "KEY", x, y, 1, kText);
    y += 16;
    auto entry = [&](const std::vector<const char*>& lines, auto mark) {
        mark(Vec2(x + 5, y + 4));
        for (const char* line : lines) {
            render::drawText(canvas, line, x + 16, y, 1, kDimText);
            y += render::kLineHeight;
        }
        y += 6;
    };
    entry({"outline, as the", "collision rule", "sees it"},
          [&](Vec2 p) { render::drawLine(canvas, p - Vec2(5, 0), p + Vec2(5, 0), kRadiiColors[0]); });
    entry({"spoke to a sample"}, [&](Vec2 p) {
        render::drawLine(canvas, p - Vec2(5, 0), p + Vec2(5, 0), dimmed(kRadiiColors[0], 110));
    });
    entry({"sample point,", "its angle as the", "file writes it"}, [&](Vec2 p) {
        render::fillRect(canvas, static_cast<int>(p.x()) - 1, static_cast<int>(p.y()) - 1, 3, 3, kText);
    });
    entry({"centre of radii"}, [&](Vec2 p) {
        render::drawLine(canvas, p - Vec2(5, 0), p + Vec2(5, 0), kRadiiColors[0]);
        render::drawLine(canvas, p - Vec2(0, 5), p + Vec2(0, 5), kRadiiColors[0]);
        render::drawCircle(canvas, p, 3, kRadiiColors[0]);
    });
    entry({"sprite's own axes", "through its centre"},
          [&](Vec2 p) { drawArrow(canvas, p - Vec2(5, 0), p + Vec2(5, 0), kAxes); });
    entry({"the image, with", "its pixel grid"}, [&](Vec2 p) {
        render::fillRect(canvas, static_cast<int>(p.x()) - 5, static_cast<int>(p.y()) - 4, 10, 9, kImageArea);
    });
}

}  // namespace

void addView(cli::Command& app, ViewArgs& args) {
    app.footer(
        "Draw a bounds file over its sprite with the game's renderer: each Bound's outline exactly "
        "as the "
        "collision rule sees it (\"interpolate\": true joins the samples with straight edges; false gives "
        "each "
        "sample an arc of its radius up to the bisectors between samples, with radial steps there), the "
        "spokes "
        "from the centre to every sample, labelled with the angle as the file writes it, the centres, the "
        "sprite's "
        "bound-space axes, and a compass for the angle convention. --scale, --rotate and --flip place the "
        "sprite "
        "in the world as the game would (M = T·R·S; --flip mirrors left-right). Small sprites are zoomed so "
        "that "
        "they are readable. The sprite is NAME.png (or NAME.gif, or another image format) beside "
        "NAME.bounds.json unless --sprite says otherwise. "
        "The "
        "picture is written atomically.");
    app.option("file", args.file, "The bounds file (.bounds.json)").required();
    app.option("--sprite", args.sprite,
               "The sprite to draw under the bounds (default: found beside the file)");
    app.option("--scale", args.scale, "World scale factor K > 0 (default 1)", cli::above(0.0));
    app.option("--rotate", args.rotate, "World rotation in degrees, counter-clockwise (default 0)");
    app.flag("--flip", args.flip, "Mirror left-right (world scale x = -K)");
    app.option("--zoom", args.zoom,
               "Canvas pixels per world unit (default: fit the drawing; whole numbers for upright sprites)",
               {0, 200});
    app.option("-o,--output", args.output, "The picture to write (.png)").required();
    app.flag("-q,--quiet", args.quiet, "Print only errors and the file written");
}

namespace {

// The flags' values in range; the first that is not, as an error.
std::optional<Error> checkArgs(const ViewArgs& args) {
    if (!endsWith(args.output, ".png"))
        return Error{args.output, 0, 0, "the output is not a .png file", "-o OUT.png"};
    return std::nullopt;
}

// What the picture shows: the bounds as the game loads them, the file's own order and values (for
// the labels), and the sprite under them, if one is found.
struct Subject {
    BoundsPtr bounds;
    BoundsSpec spec;
    std::string spritePath;
    render::Image sprite;
};

Result<Subject> loadSubject(const ViewArgs& args) {
    // Exactly the loader the game uses decides whether the file is valid.
    FileReader reader = diskReader();
    Result<BoundsPtr> bounds = loadBounds(args.file, reader);
    if (!bounds) return bounds.error();
    Result<BoundsSpec> spec = parseBounds(*reader(args.file));
    if (!spec) return spec.error();
    Subject subject{*bounds, std::move(*spec), args.sprite, {}};
    if (subject.spritePath.empty())
        for (const std::string& candidate : spriteCandidates(args.file)) {
            std::error_code ec;
            if (fs::is_regular_file(candidate, ec)) {
                subject.spritePath = candidate;
                break;
            }
        }
    if (!subject.spritePath.empty()) {
        Result<render::Image> loaded = render::loadImage(subject.spritePath);
        if (!loaded) return loaded.error();
        subject.sprite = std::move(*loaded);
    }
    if (sameFile(args.output, args.file) ||
        (!subject.spritePath.empty() && sameFile(args.output, subject.spritePath)))
        return Error{args.output, 0, 0, "the output would overwrite the bounds file or the sprite",
                     "another file name for the picture"};
    return subject;
}

// The sprite placed in the world, what the drawing spans there (the image, the outlines, the
// centres and the origin), and the zoom that fits it.
struct Layout {
    Transform world;
    Mat3 m;
    double halfW = 0, halfH = 0;  // half the image, in sprite pixels
    std::vector<Vec2> imageCorners, extent;
    Vec2 low, high;
    double zoom = 1;
};

Layout layOut(const ViewArgs& args, const Subject& subject) {
    Layout l{Transform(Vec2::Zero(), degToRad(args.rotate),
                       Vec2(args.flip ? -args.scale : args.scale, args.scale)),
             Mat3::Identity(),
             subject.sprite.width() / 2.0,
             subject.sprite.height() / 2.0,
             {},
             {Vec2::Zero()},
             Vec2::Zero(),
             Vec2::Zero(),
             1};
    l.m = l.world.matrix();
    if (!subject.sprite.empty())
        for (Vec2 corner : {Vec2(-l.halfW, -l.halfH), Vec2(l.halfW, -l.halfH), Vec2(l.halfW, l.halfH),
                            Vec2(-l.halfW, l.halfH)})
            l.imageCorners.push_back(l.world.apply(corner));
    l.extent.insert(l.extent.end(), l.imageCorners.begin(), l.imageCorners.end());
    for (const Bound& r : *subject.bounds) {
        std::vector<Vec2> outline = boundOutline(r, l.m);
        l.extent.insert(l.extent.end(), outline.begin(), outline.end());
        l.extent.push_back(l.world.apply(r.centre()));
    }
    l.low = l.extent[0], l.high = l.extent[0];
    for (const Vec2& p : l.extent) {
        l.low = l.low.cwiseMin(p);
        l.high = l.high.cwiseMax(p);
    }
    Vec2 size = (l.high - l.low).cwiseMax(Vec2(1e-6, 1e-6));
    l.zoom = std::min(
        {(kDrawingWidth - 2 * kMargin) / size.x(), (kDrawingHeight - 2 * kMargin) / size.y(), kMaxZoom});
    // Whole canvas pixels per sprite pixel keep upright pixel art crisp.
    if (l.zoom >= 2 && std::fmod(reduceDegrees(args.rotate), 90.0) == 0) l.zoom = std::floor(l.zoom);
    if (args.zoom > 0) l.zoom = args.zoom;
    return l;
}

using HeaderLines = std::vector<std::pair<std::string, Color>>;

// The header's lines: the files, each bound's samples and centre, the world and the view.
HeaderLines headerLines(const ViewArgs& args, const Subject& subject, double zoom) {
    HeaderLines header;
    header.push_back(
        {args.file + (subject.spritePath.empty() ? "  (no sprite found)" : "  over  " + subject.spritePath),
         kText});
    const BoundsSpec& spec = subject.spec;
    for (std::size_t k = 0; k < spec.radii.size(); ++k) {
        const BoundSpec& r = spec.radii[k];
        std::string line = (spec.radii.size() > 1 ? "radii " + std::to_string(k + 1) + ": " : std::string()) +
                           std::to_string(r.samples.size()) + " samples, centre (" + number(r.centre.x()) +
                           ", " + number(r.centre.y()) + "), interpolate " +
                           (r.interpolate ? "true: straight edges" : "false: arcs to the bisectors");
        header.push_back({line, kRadiiColors[k % std::size(kRadiiColors)]});
    }
    header.push_back({"world: scale " + number(args.scale, 4) + ", rotate " + number(args.rotate, 4) +
                          " deg, flip " + (args.flip ? "yes" : "no") +
                          "   view: 1 sprite px = " + number(zoom * args.scale, 3) + " canvas px",
                      kDimText});
    return header;
}

// Where the world sits on the canvas: the extent centred in the drawing area, below the header,
// with the sprite's pixel edges on canvas pixel edges when the zoom is whole.
struct Placement {
    int headerHeight = 0, height = 0;
    render::View view;
    Vec2 origin;
    Mat3 toCanvas;
};

Placement placeOnCanvas(const ViewArgs& args, const Layout& l, std::size_t headerLineCount) {
    const int headerHeight = 8 + static_cast<int>(headerLineCount) * render::kLineHeight + 6;
    const int height = headerHeight + kDrawingHeight;
    Placement p{headerHeight, height, render::View(kWidth, height), Vec2::Zero(), Mat3::Identity()};
    p.view.setZoom(l.zoom);
    Vec2 middle = (l.low + l.high) / 2;
    Vec2 origin(kDrawingWidth / 2.0 - l.zoom * middle.x(),
                headerHeight + kDrawingHeight / 2.0 + l.zoom * middle.y());
    double edgeX = l.zoom * args.scale * l.halfW, edgeY = l.zoom * args.scale * l.halfH;
    p.origin = Vec2(std::round(origin.x() - edgeX) + edgeX, std::round(origin.y() - edgeY) + edgeY);
    p.view.setCentre(Vec2((kWidth / 2.0 - p.origin.x()) / l.zoom, (p.origin.y() - height / 2.0) / l.zoom));
    p.toCanvas = p.view.matrix() * l.m;
    return p;
}

void drawHeader(render::Canvas& canvas, const HeaderLines& header, int headerHeight) {
    render::fillRect(canvas, 0, 0, kWidth, headerHeight - 2, Color{14, 15, 22, 255});
    for (std::size_t i = 0; i < header.size(); ++i)
        render::drawText(canvas, fitWidth(header[i].first, kWidth - 16), 8,
                         8 + static_cast<int>(i) * render::kLineHeight, 1, header[i].second);
}

// The image's rectangle (its transparent pixels show as this colour) and, when large enough, its
// pixel grid, then the sprite.
void drawImage(render::Canvas& canvas, const render::Image& sprite, const Layout& l, const Placement& p,
               double scale) {
    if (sprite.empty()) return;
    std::vector<Vec2> corners;
    for (const Vec2& c : l.imageCorners) corners.push_back(p.view.toCanvas(c));
    render::fillPolygon(canvas, corners, kImageArea);
    if (l.zoom * scale >= 6) {
        for (int i = 0; i <= sprite.width(); ++i)
            render::drawLine(canvas, render::transformPoint(p.toCanvas, Vec2(i - l.halfW, -l.halfH)),
                             render::transformPoint(p.toCanvas, Vec2(i - l.halfW, l.halfH)), kPixelGrid);
        for (int j = 0; j <= sprite.height(); ++j)
            render::drawLine(canvas, render::transformPoint(p.toCanvas, Vec2(-l.halfW, j - l.halfH)),
                             render::transformPoint(p.toCanvas, Vec2(l.halfW, j - l.halfH)), kPixelGrid);
    }
    render::drawSprite(canvas, sprite, p.toCanvas);
}

// Labels drawn where no earlier one is: a label that would overlap is left out.
class Labels {
  public:
    explicit Labels(render::Canvas& canvas) : canvas_(canvas) {}
    // Draws `text` centred at `at` unless it would overlap a label already drawn; whether it did.
    bool place(const std::string& text, const Vec2& at, Color color) {
        Label label = labelAt(text, at);
        for (const Label& other : placed_)
            if (label.overlaps(other)) return false;
        placed_.push_back(label);
        render::drawText(canvas_, text, label.x, label.y, 1, color);
        return true;
    }

  private:
    render::Canvas& canvas_;
    std::vector<Label> placed_;
};

// The sprite's own axes through its centre (bound space, under the world transform), each as long
// as the drawing reaches along it, plus a little, labelled +x and +y.
void drawAxes(render::Canvas& canvas, Labels& labels, const Layout& l, const Placement& p) {
    auto axisEnds = [&](const Vec2& boundDir) {
        Vec2 w = l.world.linear() * boundDir;
        double length = w.norm();  // world units per bound unit along this axis
        Vec2 u = w / length;
        double low = 0, high = 0;
        for (const Vec2& e : l.extent) {
            low = std::min(low, e.dot(u));
            high = std::max(high, e.dot(u));
        }
        double extra = 12 / (l.zoom * length);
        return std::pair(render::transformPoint(p.toCanvas, boundDir * (low / length - extra)),
                         render::transformPoint(p.toCanvas, boundDir * (high / length + extra)));
    };
    Vec2 o = render::transformPoint(p.toCanvas, Vec2::Zero());
    auto [xStart, xEnd] = axisEnds(Vec2::UnitX());
    auto [yStart, yEnd] = axisEnds(Vec2::UnitY());
    render::drawLine(canvas, xStart, o, dimmed(kAxes, 140));
    render::drawLine(canvas, yStart, o, dimmed(kAxes, 140));
    drawArrow(canvas, o, xEnd, kAxes);
    drawArrow(canvas, o, yEnd, kAxes);
    labels.place("+x", xEnd + (xEnd - o).normalized() * 10, kAxes);
    labels.place("+y", yEnd + (yEnd - o).normalized() * 10, kAxes);
}

// Each bound: spokes to its samples, its outline, its sample points, its centre.
void drawRadii(render::Canvas& canvas, Labels& labels, const Bounds& radii, const Mat3& toCanvas) {
    for (std::size_t k = 0; k < radii.size(); ++k) {
        Color color = kRadiiColors[k % std::size(kRadiiColors)];
        Vec2 centre = render::transformPoint(toCanvas, radii[k].centre());
        std::vector<Vec2> points = boundSamplePoints(radii[k], toCanvas);
        for (const Vec2& p : points) render::drawLine(canvas, centre, p, dimmed(color, 110));
        render::drawPolygon(canvas, boundOutline(radii[k], toCanvas), color);
        for (const Vec2& p : points)
            render::fillRect(canvas, static_cast<int>(std::floor(p.x())) - 1,
                             static_cast<int>(std::floor(p.y())) - 1, 3, 3, kText);
        render::drawLine(canvas, centre - Vec2(5, 0), centre + Vec2(5, 0), color);
        render::drawLine(canvas, centre - Vec2(0, 5), centre + Vec2(0, 5), color);
        render::drawCircle(canvas, centre, 3, color);
        if (radii.size() > 1) labels.place("C" + std::to_string(k + 1), centre + Vec2(10, 10), color);
    }
}

struct LabelCount {
    std::size_t samples = 0, labelled = 0;
};

// Each sample's angle as the file writes it, past its tip; drawn last, so no line crosses them.
LabelCount labelSamples(Labels& labels, const BoundsSpec& spec, const Mat3& toCanvas) {
    LabelCount count;
    for (const BoundSpec& r : spec.radii) {
        Vec2 centre = render::transformPoint(toCanvas, r.centre);
        for (const DegreeSample& s : r.samples) {
            double sn, cs;
            trig::sincos(degToRad(reduceDegrees(s[0])), sn, cs);
            Vec2 tip = render::transformPoint(toCanvas, r.centre + s[1] * Vec2(cs, sn));
            Vec2 out = (tip - centre).norm() > 0 ? Vec2((tip - centre).normalized()) : Vec2(Vec2::UnitX());
            std::string text = number(s[0], 3);
            render::TextSize ts = render::measureText(text, 1);
            Vec2 at = tip + out * (7 + 0.5 * std::fabs(out.x()) * ts.width);
            ++count.samples;
            count.labelled += labels.place(text, at, kText);
        }
    }
    return count;
}

}  // namespace

int runView(const ViewArgs& args) {
    if (std::optional<Error> error = checkArgs(args)) return fail(*error);
    Result<Subject> subject = loadSubject(args);
    if (!subject) return fail(subject.error());
    const Bounds& radii = *subject->bounds;

    const Layout layout = layOut(args, *subject);
    // Header text first: its height decides where the drawing starts.
    const HeaderLines header = headerLines(args, *subject, layout.zoom);
    const Placement placement = placeOnCanvas(args, layout, header.size());

    render::Canvas canvas(kWidth, placement.height);
    canvas.clear(kBackground);
    drawHeader(canvas, header, placement.headerHeight);
    drawImage(canvas, subject->sprite, layout, placement, args.scale);
    Labels labels(canvas);
    drawAxes(canvas, labels, layout, placement);
    drawRadii(canvas, labels, radii, placement.toCanvas);
    const LabelCount count = labelSamples(labels, subject->spec, placement.toCanvas);
    drawKey(canvas, placement.headerHeight - 2, placement.height - placement.headerHeight + 2);

    if (std::optional<Error> error = render::savePng(canvas, args.output)) return fail(*error);
    if (!args.quiet) {
        std::printf("%s: %zu radii, %zu samples", args.file.c_str(), radii.size(), count.samples);
        if (count.labelled < count.samples)
            std::printf(" (%zu labelled; the other labels would overlap)", count.labelled);
        std::printf("\n");
        std::printf("zoom %s, sprite origin at canvas (%s, %s)\n", number(layout.zoom, 4).c_str(),
                    number(placement.origin.x(), 3).c_str(), number(placement.origin.y(), 3).c_str());
    }
    std::printf("wrote %s (%dx%d)\n", args.output.c_str(), kWidth, placement.height);
    return 0;
}

}  // namespace polar::bounds_tool
