#include "app/hud/backdrop.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <vector>

#include "app/hud/lettering.h"
#include "polar/render/image.h"
#include "polar/splitmix64.h"

namespace polar::game {

using render::Color;

namespace {

// The still pictures are one screen (640 × 360) and tile both ways, so a drifting one wraps
// without a seam.
constexpr int kTileWidth = 640;
constexpr int kTileHeight = 360;

std::uint64_t mix(std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0) {
    std::uint64_t state = a * 0x9E3779B97F4A7C15ull ^ b * 0xC2B2AE3D27D4EB4Full ^ c * 0x165667B19E3779F9ull;
    return splitmix64(state);
}

// A number in [0, 1) from a hash.
double unit(std::uint64_t h) {
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

// Value noise that repeats every kTileWidth × kTileHeight pixels: random values on a lattice of
// cellsX × cellsY cells over the tile (drawn once, when it is made), blended with smoothstep
// weights (3t² − 2t³).
class TiledNoise {
  public:
    TiledNoise(int cellsX, int cellsY, std::uint64_t seed)
        : cellsX_(cellsX), cellsY_(cellsY), values_(static_cast<std::size_t>((cellsX + 1) * (cellsY + 1))) {
        for (int cy = 0; cy <= cellsY; ++cy)
            for (int cx = 0; cx <= cellsX; ++cx)
                values_[static_cast<std::size_t>(cy * (cellsX + 1) + cx)] =
                    unit(mix(seed, cx % cellsX, cy % cellsY));
    }
    double at(int x, int y) const {
        const double fx = static_cast<double>(x) * cellsX_ / kTileWidth;
        const double fy = static_cast<double>(y) * cellsY_ / kTileHeight;
        const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
        const double tx = fx - ix, ty = fy - iy;
        const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
        auto v = [&](int cx, int cy) { return values_[static_cast<std::size_t>(cy * (cellsX_ + 1) + cx)]; };
        const double top = v(ix, iy) + (v(ix + 1, iy) - v(ix, iy)) * sx;
        const double bottom = v(ix, iy + 1) + (v(ix + 1, iy + 1) - v(ix, iy + 1)) * sx;
        return top + (bottom - top) * sy;
    }

  private:
    int cellsX_, cellsY_;
    std::vector<double> values_;
};

// Octaves of it, from cells of 160 × 180 pixels down (to 10 × 10 with five), each half the weight
// of the one before; in [0, 1).
class Clouds {
  public:
    explicit Clouds(std::uint64_t seed, int octaves = 5) {
        for (int k = 0; k < octaves; ++k) octaves_.emplace_back(4 << k, (9 << k) / 4, seed + k);
    }
    double at(int x, int y) const {
        double sum = 0, weight = 1, total = 0;
        for (const TiledNoise& octave : octaves_) {
            sum += weight * octave.at(x, y);
            total += weight;
            weight *= 0.5;
        }
        return sum / total;
    }

  private:
    std::vector<TiledNoise> octaves_;
};

// A smooth, clamped shaping of a cloud value: 0 below `from`, rising to 1 at `to`.
double ramp(double v, double from, double to) {
    const double t = std::clamp((v - from) / (to - from), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

std::uint8_t channel(double v) {
    return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5);
}

Color mixColor(double r, double g, double b, double a = 255) {
    return Color{channel(r), channel(g), channel(b), channel(a)};
}

render::Image makeStarfield() {
    render::Image image(kTileWidth, kTileHeight);
    const Clouds purples(11), teals(23);
    const TiledNoise grains(128, 72, 31);
    for (int y = 0; y < kTileHeight; ++y) {
        for (int x = 0; x < kTileWidth; ++x) {
            const double purple = ramp(purples.at(x, y), 0.45, 0.8);
            const double teal = ramp(teals.at(x, y), 0.5, 0.85);
            const double grain = grains.at(x, y);
            double r = 6 + 58 * purple + 6 * teal * grain;
            double g = 6 + 14 * purple + 44 * teal;
            double b = 20 + 70 * purple + 58 * teal;
            // The far stars: about one pixel in 400, dim, a little bluer or redder.
            const std::uint64_t h = mix(37, x, y);
            if (h % 400 == 0) {
                const double shine = 50 + 90 * unit(mix(h));
                r += shine * (h & 1 ? 0.8 : 1.0), g += shine * 0.85, b += shine * (h & 1 ? 1.0 : 0.75);
            }
            image.setPixel(x, y, mixColor(r, g, b));
        }
    }
    return image;
}

render::Image makeFog() {
    render::Image image(kTileWidth, kTileHeight);
    const Clouds murks(41);
    for (int y = 0; y < kTileHeight; ++y) {
        for (int x = 0; x < kTileWidth; ++x) {
            const double murk = murks.at(x, y);
            const double low = static_cast<double>(y) / kTileHeight;  // the mist settles low
            image.setPixel(x, y,
                           mixColor(6 + 18 * murk * murk + 4 * low, 14 + 34 * murk + 10 * low,
                                    16 + 30 * murk + 9 * low));
        }
    }
    return image;
}

render::Image makeFogWisps() {
    render::Image image(kTileWidth, kTileHeight);
    const Clouds wisps(53, 4);
    for (int y = 0; y < kTileHeight; ++y) {
        for (int x = 0; x < kTileWidth; ++x) {
            const double wisp = ramp(wisps.at(x, y), 0.5, 0.78);
            if (wisp > 0) image.setPixel(x, y, mixColor(150, 210, 190, 55 * wisp));
        }
    }
    return image;
}

render::Image makeStorm() {
    render::Image image(kTileWidth, kTileHeight);
    const Clouds clouds(61);
    for (int y = 0; y < kTileHeight; ++y) {
        for (int x = 0; x < kTileWidth; ++x) {
            const double cloud = clouds.at(x, y);
            const double billow = ramp(cloud, 0.35, 0.75);
            const double high = 1.0 - static_cast<double>(y) / kTileHeight;  // lit from above
            image.setPixel(x, y,
                           mixColor(10 + 34 * billow * high + 8 * cloud, 12 + 38 * billow * high + 10 * cloud,
                                    22 + 56 * billow * high + 18 * cloud));
        }
    }
    return image;
}

render::Image makeCavern() {
    render::Image image(kTileWidth, kTileHeight);
    const Clouds rocks(71), veins(79);
    const TiledNoise strataWide(8, 36, 73), strataFine(16, 72, 74);
    for (int y = 0; y < kTileHeight; ++y) {
        for (int x = 0; x < kTileWidth; ++x) {
            // Strata: noise in cells eight times wider than tall; thin mineral veins where another
            // noise crosses a band, in the teal of the cave's crystals; a warm glow from below,
            // where the embers rise.
            const double rock = rocks.at(x, y);
            const double strata = 0.6 * strataWide.at(x, y) + 0.4 * strataFine.at(x, y);
            const double vein = 1.0 - std::min(1.0, std::abs(veins.at(x, y) - 0.5) * 60);
            const double low = static_cast<double>(y) / kTileHeight;
            const double glow = low * low * low;
            image.setPixel(x, y,
                           mixColor(12 + 16 * rock + 10 * strata + 6 * vein + 34 * glow,
                                    8 + 9 * rock + 6 * strata + 22 * vein + 12 * glow,
                                    18 + 22 * rock + 12 * strata + 24 * vein + 2 * glow));
        }
    }
    return image;
}

// Each still picture is made the first time a frame needs it (tens of ms), then shared by every
// thread.
const render::Image& starfieldPicture() {
    static const render::Image made = makeStarfield();  // deep blue, a nebula, the faint far stars
    return made;
}
const render::Image& fogPicture() {
    static const render::Image made = makeFog();  // a dark green murk
    return made;
}
const render::Image& fogWispsPicture() {
    static const render::Image made = makeFogWisps();  // translucent wisps over the murk
    return made;
}
const render::Image& stormPicture() {
    static const render::Image made = makeStorm();  // low slate clouds, lit from above
    return made;
}
const render::Image& cavernPicture() {
    static const render::Image made = makeCavern();  // dark rock strata, a warm glow below
    return made;
}

// Draws a tile shifted by (dx, dy) pixels (any real numbers; whole pixels are used), repeated to
// fill the canvas.
void drawTiled(render::DrawList& list, const render::Image& tile, int width, int height, double dx,
               double dy) {
    const auto wrap = [](double v, int period) {
        long long whole = static_cast<long long>(std::floor(v));
        return static_cast<int>(((whole % period) + period) % period);
    };
    const int ox = wrap(dx, tile.width()), oy = wrap(dy, tile.height());
    for (int top = oy - tile.height(); top < height; top += tile.height())
        for (int left = ox - tile.width(); left < width; left += tile.width())
            if (left + tile.width() > 0 && top + tile.height() > 0)
                list.drawSprite(tile, Vec2(left + tile.width() / 2.0, top + tile.height() / 2.0));
}

// Stars in a layer: `count` of them, drifting by (vx, vy) pixels a second, twinkling.
void drawStars(render::DrawList& list, int width, int height, double seconds, std::uint64_t seed, int count,
               double vx, double vy, int brightness, bool big) {
    for (int i = 0; i < count; ++i) {
        const std::uint64_t h = mix(seed, i);
        const double x0 = unit(h) * width, y0 = unit(mix(h, 1)) * height;
        double x = std::fmod(x0 + vx * seconds, width), y = std::fmod(y0 + vy * seconds, height);
        if (x < 0) x += width;
        if (y < 0) y += height;
        // A slow twinkle: a triangle wave on the star's own period and phase.
        const double period = 1.5 + 2.5 * unit(mix(h, 2));
        const double phase = std::fmod(seconds / period + unit(mix(h, 3)), 1.0);
        const double twinkle = 0.6 + 0.4 * std::abs(2 * phase - 1);
        const int a = static_cast<int>(brightness * twinkle);
        const Color color = h & 4 ? Color{255, 236, 210, channel(a)} : Color{200, 220, 255, channel(a)};
        const int px = static_cast<int>(x), py = static_cast<int>(y);
        list.blendPixel(px, py, color);
        if (big && (h & 3) == 0) {  // one in four near stars is a small cross
            const Color arm = color.withAlpha(channel(a * 0.45));
            list.blendPixel(px - 1, py, arm), list.blendPixel(px + 1, py, arm);
            list.blendPixel(px, py - 1, arm), list.blendPixel(px, py + 1, arm);
        }
    }
}

void drawRain(render::DrawList& list, int width, int height, double seconds) {
    constexpr int kDrops = 170;
    for (int i = 0; i < kDrops; ++i) {
        const std::uint64_t h = mix(97, i);
        const double speed = 380 + 240 * unit(mix(h, 1));  // nearer drops fall faster and longer
        const double length = speed / 60;
        const double x0 = unit(h) * (width + 120), y0 = unit(mix(h, 2)) * (height + 40);
        double y = std::fmod(y0 + speed * seconds, height + 40) - 20;
        double x = std::fmod(x0 - speed * 0.3 * seconds, width + 120);
        if (x < 0) x += width + 120;
        x -= 60;
        const Color color{150, 170, 215, channel(50 + 70 * (speed - 380) / 240)};
        list.drawLine(Vec2(x, y), Vec2(x - length * 0.3, y - length), color);
    }
}

// A strike's bolt: a jagged line from the top of the sky down, with one branch, as the seed says.
void drawBolt(render::DrawList& list, int width, int height, std::uint64_t strike, double strength) {
    std::array<Vec2, 12> main{};
    double x = width * (0.1 + 0.8 * unit(mix(strike, 1)));
    const double bottom = height * (0.45 + 0.35 * unit(mix(strike, 2)));
    for (std::size_t i = 0; i < main.size(); ++i) {
        const double y = bottom * static_cast<double>(i) / (main.size() - 1);
        main[i] = Vec2(x, y);
        x += (unit(mix(strike, 10 + i)) - 0.5) * 34;
    }
    std::array<Vec2, 6> branch{};
    const std::size_t from = 3 + mix(strike, 3) % 4;
    branch[0] = main[from];
    const double side = mix(strike, 4) & 1 ? 1.0 : -1.0;
    for (std::size_t i = 1; i < branch.size(); ++i)
        branch[i] = branch[i - 1] + Vec2(side * (8 + 12 * unit(mix(strike, 30 + i))), bottom / 18);
    const Color glow{150, 170, 255, channel(90 * strength)};
    const Color core{235, 240, 255, channel(255 * strength)};
    for (const Vec2& offset : {Vec2(-1, 0), Vec2(1, 0)}) {
        std::array<Vec2, main.size()> moved{};
        for (std::size_t i = 0; i < main.size(); ++i) moved[i] = main[i] + offset;
        list.drawPolyline(moved, glow);
    }
    list.drawPolyline(main, core);
    list.drawPolyline(branch, core.withAlpha(channel(170 * strength)));
}

// Embers rising from the cave's floor, swaying, glowing and fading as they climb.
void drawEmbers(render::DrawList& list, int width, int height, double seconds) {
    constexpr int kEmbers = 48;
    for (int i = 0; i < kEmbers; ++i) {
        const std::uint64_t h = mix(113, i);
        const double rise = 10 + 16 * unit(mix(h, 1));
        const double travel = height + 20;
        const double climbed = std::fmod(unit(mix(h, 2)) * travel + rise * seconds, travel);
        const double y = height + 10 - climbed;
        // A sway of ±6 pixels: a triangle wave, so no trigonometry is needed for the same bytes.
        const double sway = std::fmod(seconds / (2 + 2 * unit(mix(h, 3))) + unit(mix(h, 4)), 1.0);
        const double x = unit(h) * width + 12 * (std::abs(2 * sway - 1) - 0.5);
        const double fade = 1.0 - climbed / travel;
        const Color core{255, 190, 90, channel(220 * fade)};
        const int px = static_cast<int>(x), py = static_cast<int>(y);
        list.fillRect(px - 1, py - 1, 3, 3, Color{255, 120, 40, channel(50 * fade)});
        list.blendPixel(px, py, core);
    }
}

double secondsAt(std::uint64_t tick, double alpha) {
    return (static_cast<double>(tick) + alpha) / 60.0;
}

}  // namespace

SceneLook lookFor(Backdrop backdrop) {
    switch (backdrop) {
        case Backdrop::Starfield:
            return {backdrop, Color{140, 225, 255, 255}};
        case Backdrop::Fog:
            return {backdrop, Color{160, 255, 190, 255}};
        case Backdrop::Storm:
            return {backdrop, Color{255, 232, 120, 255}};
        case Backdrop::Cavern:
            return {backdrop, Color{255, 180, 110, 255}};
        case Backdrop::Plain:
            break;
    }
    return {Backdrop::Plain, kHudText};
}

Backdrop backdropOf(const Game& game) {
    return backdropFor(game.rules(), game.scenePath());
}

Backdrop backdropFor(const SceneRules& rules, const std::string& scenePath) {
    if (rules.backdrop) return *rules.backdrop;
    const std::string name = std::filesystem::path(scenePath).stem().string();
    if (name == "cave") return Backdrop::Cavern;
    if (name == "field") return Backdrop::Starfield;
    if (name == "ghosts") return Backdrop::Fog;
    if (name == "storm") return Backdrop::Storm;
    return Backdrop::Plain;
}

std::string aboutBackdrop(Backdrop backdrop) {
    switch (backdrop) {
        case Backdrop::Starfield:
            return "OPEN SPACE UNDER THE STARS AND A NEBULA.";
        case Backdrop::Fog:
            return "A GREEN FOG DRIFTS BY.";
        case Backdrop::Storm:
            return "A STORM OF RAIN AND LIGHTNING.";
        case Backdrop::Cavern:
            return "EMBERS RISE IN THE DEEP.";
        case Backdrop::Plain:
            break;
    }
    return "";
}

double lightningAt(std::uint64_t seed, std::uint64_t tick, double alpha) {
    // Strikes in slots of 7 s (420 ticks); each slot's strike at a drawn moment in its first 4 s,
    // so strikes are 3 to 11 s apart, 7 on average. A strike is two flickers: 6 ticks up, a dip,
    // and a second flash dying away over 24 ticks.
    constexpr std::uint64_t kSlot = 420;
    const std::uint64_t slot = tick / kSlot;
    const std::uint64_t at = slot * kSlot + mix(seed, slot, 0x5707) % 240;
    const double t = static_cast<double>(tick) + alpha - static_cast<double>(at);
    if (t < 0 || t > 36) return 0;
    if (t < 6) return t / 6;
    if (t < 10) return 0.25;
    return std::max(0.0, 1.0 - (t - 10) / 26);
}

void drawBackdrop(render::DrawList& list, int width, int height, Backdrop backdrop, std::uint64_t seed,
                  std::uint64_t tick, double alpha, const EffectLevels& levels) {
    const double s = secondsAt(tick, alpha);
    switch (backdrop) {
        case Backdrop::Plain:
            list.clear(Color{6, 6, 14, 255});
            return;
        case Backdrop::Starfield:
            // Three depths: the nebula and its far stars barely drift, two star layers pass faster.
            drawTiled(list, starfieldPicture(), width, height, -1.5 * s, 0.6 * s);
            drawStars(list, width, height, s, 5, 90, -5, 2, 150, false);
            drawStars(list, width, height, s, 7, 40, -12, 4.8, 230, true);
            return;
        case Backdrop::Fog:
            drawTiled(list, fogPicture(), width, height, 4 * s, 0);
            drawTiled(list, fogWispsPicture(), width, height, -11 * s, 1.5 * s);
            return;
        case Backdrop::Storm: {
            drawTiled(list, stormPicture(), width, height, -7 * s, 0);
            const double light = lightningAt(seed, tick, alpha) * std::clamp(levels.flashes, 0, 100) / 100.0;
            if (light > 0) {
                list.fillRect(0, 0, width, height, Color{170, 180, 230, channel(70 * light)});
                const std::uint64_t slot = tick / 420;
                drawBolt(list, width, height, mix(seed, slot, 0xB017), std::min(1.0, light * 1.4));
            }
            drawRain(list, width, height, s);
            return;
        }
        case Backdrop::Cavern:
            drawTiled(list, cavernPicture(), width, height, 0, 0);
            drawEmbers(list, width, height, s);
            return;
    }
}

}  // namespace polar::game
