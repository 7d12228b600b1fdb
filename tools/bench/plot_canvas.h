#pragma once
// A white RGBA image with pixels, lines and 5×7 text, shared by the benchmarks' plots.
//
// Why not the renderer's Canvas? A plot needs only lines and labels at exact pixels, and drawing
// straight into an RgbaImage keeps plots free of SDL and of the renderer's blending rules.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "plot_font.h"
#include "polar/platform/png_io.h"

namespace polar::bench {

class PlotCanvas {
  public:
    PlotCanvas(int width, int height) {
        image.width = width;
        image.height = height;
        image.pixels.assign(static_cast<std::size_t>(width) * height, 0xFFFFFFFF);
    }

    void set(int x, int y, std::uint32_t colour) {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
        image.pixels[static_cast<std::size_t>(y) * image.width + x] = colour;
    }
    void fill(int x0, int y0, int x1, int y1, std::uint32_t colour) {
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) set(x, y, colour);
    }
    // A line `thickness` pixels wide; `dash` > 0 draws dash-length on, dash-length off.
    void line(double x0, double y0, double x1, double y1, std::uint32_t colour, int thickness = 1,
              int dash = 0) {
        double length = std::hypot(x1 - x0, y1 - y0);
        int steps = std::max(1, static_cast<int>(std::ceil(length * 2)));
        for (int i = 0; i <= steps; ++i) {
            double t = static_cast<double>(i) / steps;
            if (dash > 0 && static_cast<int>(t * length / dash) % 2 == 1) continue;
            int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
            int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
            int lo = -(thickness - 1) / 2, hi = thickness / 2;
            fill(x + lo, y + lo, x + hi, y + hi, colour);
        }
    }
    // Text with its top-left corner at (x, y), `scale` pixels per font pixel; returns the width.
    int text(int x, int y, const std::string& s, std::uint32_t colour, int scale = 1) {
        int cursor = x;
        for (char c : s) {
            if (const Glyph* g = findGlyph(c)) {
                for (int row = 0; row < 7; ++row)
                    for (int col = 0; col < 5; ++col)
                        if (g->rows[row][col] == '#')
                            fill(cursor + col * scale, y + row * scale, cursor + col * scale + scale - 1,
                                 y + row * scale + scale - 1, colour);
            }
            cursor += 6 * scale;
        }
        return cursor - x;
    }
    static int textWidth(const std::string& s, int scale = 1) {
        return static_cast<int>(s.size()) * 6 * scale;
    }
    // Text drawn upward (rotated a quarter turn counter-clockwise), its baseline at x.
    void textUp(int x, int y, const std::string& s, std::uint32_t colour) {
        int cursor = y;
        for (char c : s) {
            if (const Glyph* g = findGlyph(c)) {
                for (int row = 0; row < 7; ++row)
                    for (int col = 0; col < 5; ++col)
                        if (g->rows[row][col] == '#') set(x + row, cursor - col, colour);
            }
            cursor -= 6;
        }
    }

    RgbaImage image;
};

}  // namespace polar::bench
