#pragma once
#include <climits>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"
#include "polar/render/image.h"
#include "polar/render/sprite.h"
#include "polar/render/view.h"
#include "polar/tasks.h"
#include "polar/transform.h"

namespace polar::render {

namespace detail {
struct PreparedSprite;  // a sprite set up for drawing (private to the renderer)
}  // namespace detail

// A frame's drawing, recorded and then drawn, so that several threads can share it.
//
// Why record rather than draw? Drawing call by call leaves one thread doing everything. A DrawList
// keeps the calls (the same ones as the immediate API, with the same arguments) and draw() then
// splits the canvas into horizontal bands of rows, each band drawn by one task running every
// command in order, clipped to its rows. Each pixel is still written by the same calls in the same
// order, and no call's pixels depend on which rows are drawn, so the bytes equal those of the
// immediate calls at any thread count.
// The list keeps pointers to the images it is given (they must outlive draw()) and copies
// everything else (points, text). reset() keeps the memory, so a warm frame allocates nothing.
class DrawList {
  public:
    DrawList();
    ~DrawList();
    DrawList(DrawList&&) noexcept;
    DrawList& operator=(DrawList&&) noexcept;
    DrawList(const DrawList&) = delete;
    DrawList& operator=(const DrawList&) = delete;

    // Forgets every command, keeping the memory for the next frame.
    void reset();
    // The number of commands recorded since the last reset.
    std::size_t size() const;

    // Canvas::clear, setPixel and blendPixel.
    void clear(Color color);
    void setPixel(int x, int y, Color color);
    void blendPixel(int x, int y, Color color);
    // drawSprite (sprite.h), in its three forms.
    void drawSprite(const Image& image, const Mat3& toCanvas, const SpriteStyle& style = {});
    void drawSprite(const Image& image, const View& view, const Transform& transform,
                    const SpriteStyle& style = {});
    void drawSprite(const Image& image, const Vec2& centre, const SpriteStyle& style = {});
    // The shapes of shapes.h.
    void fillRect(int x0, int y0, int w, int h, Color color);
    void drawRect(int x0, int y0, int w, int h, Color color);
    void drawLine(const Vec2& a, const Vec2& b, Color color);
    void drawPolyline(std::span<const Vec2> points, Color color);
    void drawPolygon(std::span<const Vec2> points, Color color);
    void fillPolygon(std::span<const Vec2> points, Color color);
    void fillCircle(const Vec2& centre, double radius, Color color);
    void drawCircle(const Vec2& centre, double radius, Color color);
    // drawText (text.h).
    void drawText(std::string_view text, int x, int y, int scale, Color color);

    // Draws every command in order into `canvas`, in bands of rows: on this thread when `tasks` is
    // null or has one worker, else as one task on `tasks`. The same bytes either way. Not to be
    // called on one list from two threads at once.
    void draw(Canvas& canvas, TaskSystem* tasks = nullptr) const;

    // How long the last draw() spent in its two passes, with timing on (setTiming; off by default):
    // setting the sprites up, then the bands of rows. For benchmarks and stats displays.
    struct Times {
        std::uint64_t setupNanoseconds = 0;
        std::uint64_t bandsNanoseconds = 0;
    };
    void setTiming(bool on) { timing_ = on; }
    const Times& lastTimes() const { return times_; }

    // The smallest band a task draws, in rows: each band runs through every command, so bands
    // much thinner than a sprite would repeat work.
    static constexpr std::uint32_t kMinBandRows = 16;

  private:
    struct Command;  // one recorded call (draw_list.cpp)
    // The rows [begin, end) a command may write: every row but a sprite's own (set when drawn).
    struct Rows {
        int begin = 0;
        int end = 0;
    };
    static constexpr Rows kEveryRow{INT_MIN, INT_MAX};

    // Sets up every sprite for `canvas` (its rows, and everything its rows share), on `tasks`.
    void prepareSprites(const Canvas& canvas, TaskSystem* tasks) const;
    // Draws every command, band by band, on `tasks` or this thread.
    void drawBands(Canvas& canvas, TaskSystem* tasks, std::uint32_t rows, std::uint32_t bandRows) const;

    void drawRows(Canvas& canvas, int rowBegin, int rowEnd, std::vector<double>& crossings) const;
    Command& add();

    std::vector<Command> commands_;
    std::vector<std::uint32_t> sprites_;  // the sprite commands' indices, in order
    // Per command, the rows it may write (a sprite's: from its setup, by draw()), and per sprite
    // its setup. Written by draw() before the bands run.
    mutable std::vector<Rows> rows_;
    mutable std::vector<detail::PreparedSprite> prepared_;
    std::vector<Vec2> points_;          // polylines and polygons, back to back
    std::string text_;                  // text, back to back
    std::uint32_t largestPolygon_ = 0;  // points of the largest fillPolygon since reset()
    // fillPolygon's edge crossings, one buffer per worker, grown by draw() before the bands run so
    // that the bands allocate nothing. (So draw() must not run twice at once on one list.)
    mutable std::vector<std::vector<double>> crossings_;
    bool timing_ = false;
    mutable Times times_;
};

}  // namespace polar::render
