// polarcade-art: draws the demo game's sprites procedurally (no downloads), deterministic from a seed.
//
// To regenerate the committed art and its bounds, from the repository's top folder:
//   build/bin/polarcade-art --out assets/sprites
//   for f in assets/sprites/*.png; do
//     case $f in
//       */cave.png)  build/bin/polarcade-bounds gen "$f" --container -q ;;
//       */comet.png) build/bin/polarcade-bounds gen "$f" --radii 2 -q ;;
//       *)           build/bin/polarcade-bounds gen "$f" -q ;;
//     esac
//   done
// Both steps are deterministic, so this reproduces the committed files byte for byte.
#include <cstdio>
#include <filesystem>

#include "cli.h"
#include "sprites.h"

namespace {

using polar::art::Canvas;
using polar::art::Colour;

// All sprites but the cave, zoomed, on a checkerboard that shows transparency; the cave below at 1×.
polar::RgbaImage contactSheet(const std::vector<polar::art::NamedSprite>& sprites, int zoom) {
    const int pad = 8, width = 640;
    int x = pad, y = pad, rowHeight = 0;
    struct Place {
        const Canvas* canvas;
        int x, y, zoom;
    };
    std::vector<Place> places;
    const Canvas* cave = nullptr;
    for (const auto& s : sprites) {
        if (s.name == "cave") {
            cave = &s.canvas;
            continue;
        }
        int w = s.canvas.width() * zoom, h = s.canvas.height() * zoom;
        if (x + w + pad > width) x = pad, y += rowHeight + pad, rowHeight = 0;
        places.push_back({&s.canvas, x, y, zoom});
        x += w + pad;
        rowHeight = std::max(rowHeight, h);
    }
    y += rowHeight + pad;
    if (cave) places.push_back({cave, 0, y, 1}), y += cave->height();
    Canvas sheet(width, y);
    for (int py = 0; py < y; ++py)
        for (int px = 0; px < width; ++px)
            sheet.set(px, py, ((px / 8 + py / 8) % 2) ? Colour::hex(0x101018) : Colour::hex(0x181824));
    for (const Place& p : places)
        for (int sy = 0; sy < p.canvas->height() * p.zoom; ++sy)
            for (int sx = 0; sx < p.canvas->width() * p.zoom; ++sx)
                sheet.blend(p.x + sx, p.y + sy, p.canvas->at(sx / p.zoom, sy / p.zoom));
    return sheet.image();
}

}  // namespace

int main(int argc, char** argv) {
    polar::cli::Command app{
        "Draws the demo game's sprites procedurally and writes them as PNG files (atomically). The same "
        "seed always gives the same pixels.",
        "polarcade-art"};
    std::string out;
    std::string sheet;
    std::uint64_t seed = 1979;
    int zoom = 4;
    app.option("-o,--out", out, "Folder to write the sprites into (e.g. assets/sprites)").required();
    app.option("--seed", seed, "Random seed for the rocks, comet and cave (default 1979, the committed art)");
    app.option("--sheet", sheet, "Also write a contact sheet (sprites zoomed, the cave at 1x) to this PNG");
    app.option("--zoom", zoom, "Zoom of the small sprites on the contact sheet", {1, 16});
    if (int code = app.parse(argc, argv); code >= 0) return code;

    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) {
        std::fprintf(stderr, "%s: cannot create the folder: %s; expected a writable place\n", out.c_str(),
                     ec.message().c_str());
        return polar::cli::kBadInput;
    }
    std::vector<polar::art::NamedSprite> sprites = polar::art::drawAll(seed);
    for (const auto& s : sprites) {
        std::string path = (std::filesystem::path(out) / (s.name + ".png")).generic_string();
        if (auto error = polar::savePng(s.canvas.image(), path)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 1;
        }
        std::printf("wrote %s (%dx%d)\n", path.c_str(), s.canvas.width(), s.canvas.height());
    }
    if (!sheet.empty()) {
        if (auto error = polar::savePng(contactSheet(sprites, zoom), sheet)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 1;
        }
        std::printf("wrote %s (contact sheet)\n", sheet.c_str());
    }
    return 0;
}
