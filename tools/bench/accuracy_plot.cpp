#include "accuracy_plot.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>

namespace polar::bench {
namespace {

// A 5×7 pixel font: capitals (lower case is drawn as capitals), digits and a little punctuation.
// Each glyph is seven rows of five cells, '#' for ink.
const std::map<char, std::array<const char*, 7>>& font() {
    static const std::map<char, std::array<const char*, 7>> glyphs = {
        {'0', {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."}},
        {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
        {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
        {'3', {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."}},
        {'4', {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."}},
        {'5', {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."}},
        {'6', {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."}},
        {'7', {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."}},
        {'8', {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."}},
        {'9', {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."}},
        {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
        {'B', {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."}},
        {'C', {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."}},
        {'D', {"####.", "#...#", "#...#", "#...#", "#...#", "#...#", "####."}},
        {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
        {'F', {"#####", "#....", "#....", "####.", "#....", "#....", "#...."}},
        {'G', {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"}},
        {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
        {'I', {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."}},
        {'J', {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."}},
        {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
        {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
        {'M', {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"}},
        {'N', {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"}},
        {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
        {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
        {'Q', {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"}},
        {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
        {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
        {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
        {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
        {'V', {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."}},
        {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."}},
        {'X', {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"}},
        {'Y', {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."}},
        {'Z', {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"}},
        {'.', {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."}},
        {',', {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."}},
        {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
        {'(', {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."}},
        {')', {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."}},
        {'/', {"....#", "...#.", "...#.", "..#..", ".#...", ".#...", "#...."}},
        {'%', {"##..#", "##..#", "...#.", "..#..", ".#...", "#..##", "#..##"}},
        {':', {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."}},
        {'=', {".....", ".....", "#####", ".....", "#####", ".....", "....."}},
        {'+', {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."}},
        {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
    };
    return glyphs;
}

class Canvas {
public:
    Canvas(int width, int height) {
        image_.width = width;
        image_.height = height;
        image_.pixels.assign(static_cast<std::size_t>(width) * height, 0xffffffffu);
    }

    void pixel(int x, int y, std::uint32_t colour) {
        if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
        image_.pixels[static_cast<std::size_t>(y) * image_.width + x] = colour;
    }

    void rect(int x0, int y0, int x1, int y1, std::uint32_t colour) {
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) pixel(x, y, colour);
    }

    // A straight line, one pixel wide (Bresenham).
    void line(int x0, int y0, int x1, int y1, std::uint32_t colour) {
        int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
        int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, err = dx + dy;
        for (;;) {
            pixel(x0, y0, colour);
            if (x0 == x1 && y0 == y1) return;
            int e2 = 2 * err;
            if (e2 >= dy) err += dy, x0 += sx;
            if (e2 <= dx) err += dx, y0 += sy;
        }
    }

    void disc(int cx, int cy, int r, std::uint32_t colour) {
        for (int y = -r; y <= r; ++y)
            for (int x = -r; x <= r; ++x)
                if (x * x + y * y <= r * r) pixel(cx + x, cy + y, colour);
    }

    // Text with its top-left corner at (x, y), each font cell `scale` pixels square.
    void text(int x, int y, const std::string& s, int scale, std::uint32_t colour) {
        for (char ch : s) {
            char c = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
            auto it = font().find(c);
            if (it != font().end())
                for (int row = 0; row < 7; ++row)
                    for (int col = 0; col < 5; ++col)
                        if (it->second[row][col] == '#') rect(x + col * scale, y + row * scale, x + col * scale + scale - 1,
                                                              y + row * scale + scale - 1, colour);
            x += 6 * scale;
        }
    }

    // The same, turned a quarter counter-clockwise (for a y-axis title), bottom-left at (x, y).
    void textUp(int x, int y, const std::string& s, int scale, std::uint32_t colour) {
        for (char ch : s) {
            char c = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
            auto it = font().find(c);
            if (it != font().end())
                for (int row = 0; row < 7; ++row)
                    for (int col = 0; col < 5; ++col)
                        if (it->second[row][col] == '#')
                            rect(x + row * scale, y - col * scale - scale + 1, x + row * scale + scale - 1, y - col * scale,
                                 colour);
            y -= 6 * scale;
        }
    }

    static int textWidth(const std::string& s, int scale) { return static_cast<int>(s.size()) * 6 * scale - scale; }

    RgbaImage take() { return std::move(image_); }

private:
    RgbaImage image_;
};

std::string tickText(double v) {
    char buffer[32];
    if (v >= 1 && v == std::floor(v))
        std::snprintf(buffer, sizeof buffer, "%.0f", v);
    else
        std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

// A step of 1, 2 or 5 × 10^k giving about `count` ticks over [0, top].
double niceStep(double top, int count) {
    double raw = top / count;
    double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= raw) return m * power;
    return 10 * power;
}

}  // namespace

RgbaImage scatterPlot(const PlotSpec& spec, const std::vector<PlotPoint>& points) {
    Canvas canvas(spec.width, spec.height);
    const std::uint32_t ink = 0xff202020, grid = 0xffe4e4e4, axis = 0xff606060;
    const int left = 90, right = spec.width - 30, top = 60, bottom = spec.height - 70;

    double xMin = INFINITY, xMax = 0, yMax = 0;
    for (const PlotPoint& p : points) {
        xMin = std::min(xMin, p.x);
        xMax = std::max(xMax, p.x);
        yMax = std::max(yMax, p.y);
    }
    if (points.empty()) xMin = 1, xMax = 10;
    double lo = std::pow(10.0, std::floor(std::log10(xMin))), hi = std::pow(10.0, std::ceil(std::log10(xMax)));
    if (hi <= lo) hi = lo * 10;
    double yStep = niceStep(std::max(yMax, 1e-9) * 1.1, 6);
    double yTop = std::ceil(std::max(yMax, 1e-9) * 1.1 / yStep) * yStep;
    auto px = [&](double x) { return left + static_cast<int>(std::lround((std::log10(x) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (right - left))); };
    auto py = [&](double y) { return bottom - static_cast<int>(std::lround(y / yTop * (bottom - top))); };

    // Grid and ticks: x at 1, 2, 5 × 10^k; y at the nice step.
    for (double decade = lo; decade < hi * 1.001; decade *= 10) {
        for (double m : {1.0, 2.0, 5.0}) {
            double x = decade * m;
            if (x > hi * 1.001) break;
            int X = px(x);
            canvas.line(X, top, X, bottom, grid);
            canvas.line(X, bottom, X, bottom + 5, axis);
            std::string label = tickText(x);
            canvas.text(X - Canvas::textWidth(label, 2) / 2, bottom + 10, label, 2, ink);
        }
    }
    for (double y = 0; y <= yTop * 1.0001; y += yStep) {
        int Y = py(y);
        canvas.line(left, Y, right, Y, grid);
        canvas.line(left - 5, Y, left, Y, axis);
        std::string label = tickText(std::round(y / yStep) * yStep);
        canvas.text(left - 10 - Canvas::textWidth(label, 2), Y - 7, label, 2, ink);
    }
    canvas.line(left, top, left, bottom, axis);
    canvas.line(left, bottom, right, bottom, axis);

    canvas.text((left + right - Canvas::textWidth(spec.title, 2)) / 2, 18, spec.title, 2, ink);
    canvas.text((left + right - Canvas::textWidth(spec.xLabel, 2)) / 2, spec.height - 30, spec.xLabel, 2, ink);
    canvas.textUp(14, (top + bottom + Canvas::textWidth(spec.yLabel, 2)) / 2, spec.yLabel, 2, ink);

    // Points, then labels beside them, nudged down when they would overprint an earlier label.
    std::vector<std::array<int, 4>> placed;  // x0, y0, x1, y1 of labels drawn
    for (const PlotPoint& p : points) canvas.disc(px(p.x), py(p.y), 6, p.colour);
    for (const PlotPoint& p : points) {
        int X = px(p.x), Y = py(p.y);
        int w = Canvas::textWidth(p.label, 2), h = 14;
        int x0 = X + 10 + w < right ? X + 10 : X - 10 - w;
        int y0 = Y - h / 2;
        for (bool moved = true; moved;) {
            moved = false;
            for (const auto& b : placed) {
                if (x0 <= b[2] && x0 + w >= b[0] && y0 <= b[3] && y0 + h >= b[1]) {
                    y0 = b[3] + 3;
                    moved = true;
                }
            }
        }
        canvas.text(x0, y0, p.label, 2, p.colour);
        placed.push_back({x0, y0, x0 + w, y0 + h});
    }
    return canvas.take();
}

}  // namespace polar::bench
