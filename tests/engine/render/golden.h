#pragma once
// Golden-image checks for the renderer: a canvas must equal a PNG committed under
// tests/render/golden/ pixel for pixel.
//
// To (re)create goldens after an intended change, run the tests with POLAR_UPDATE_GOLDEN=1
// (for example `POLAR_UPDATE_GOLDEN=1 build/bin/polar-render-tests`), look at every PNG that
// changed, and commit them. On a mismatch the test writes NAME.actual.png and NAME.diff.png (the
// golden dimmed, differing pixels magenta) into build/tests/render-failures/ and reports the first
// differing pixel.
#include <span>
#include <string>
#include <string_view>

#include "polar/render/canvas.h"
#include "polar/render/draw_list.h"
#include "polar/render/image.h"
#include "polar/render/shapes.h"
#include "polar/render/sprite.h"
#include "polar/render/text.h"

namespace polar::render::testing {

// Compares `actual` with golden/NAME.png (a gtest failure on mismatch), or rewrites the golden when
// POLAR_UPDATE_GOLDEN=1.
void expectMatchesGolden(const Canvas& actual, const std::string& name);

// The immediate calls under DrawList's member names, so that one scene (a generic lambda) can be
// drawn both ways.
class Immediate {
  public:
    explicit Immediate(Canvas& canvas) : canvas_(canvas) {}
    void clear(Color c) { canvas_.clear(c); }
    void drawSprite(const Image& image, const Mat3& toCanvas, const SpriteStyle& style = {}) {
        render::drawSprite(canvas_, image, toCanvas, style);
    }
    void fillRect(int x, int y, int w, int h, Color c) { render::fillRect(canvas_, x, y, w, h, c); }
    void drawRect(int x, int y, int w, int h, Color c) { render::drawRect(canvas_, x, y, w, h, c); }
    void drawLine(const Vec2& a, const Vec2& b, Color c) { render::drawLine(canvas_, a, b, c); }
    void drawPolyline(std::span<const Vec2> p, Color c) { render::drawPolyline(canvas_, p, c); }
    void drawPolygon(std::span<const Vec2> p, Color c) { render::drawPolygon(canvas_, p, c); }
    void fillPolygon(std::span<const Vec2> p, Color c) { render::fillPolygon(canvas_, p, c); }
    void fillCircle(const Vec2& centre, double r, Color c) { render::fillCircle(canvas_, centre, r, c); }
    void drawCircle(const Vec2& centre, double r, Color c) { render::drawCircle(canvas_, centre, r, c); }
    void drawText(std::string_view text, int x, int y, int scale, Color c) {
        render::drawText(canvas_, text, x, y, scale, c);
    }

  private:
    Canvas& canvas_;
};

// Draws `list` over copies of `background` with no task system, on ThreadPools of 1, 2, 3 and 8
// workers, and in bands of 1, 5 and 16 rows drawn last band first; each must match golden NAME.
void expectListMatchesGolden(const Canvas& background, const DrawList& list, const std::string& name);

// A golden scene drawn both ways: immediately over a copy of `background`, and recorded in a
// DrawList drawn at every thread count above. `scene(painter)` takes an Immediate& or a DrawList&.
template <class Scene>
void expectGoldenAtEveryThreadCount(const Canvas& background, const std::string& name, Scene&& scene) {
    Canvas canvas = background.clone();
    Immediate immediate(canvas);
    scene(immediate);
    expectMatchesGolden(canvas, name);
    DrawList list;
    scene(list);
    expectListMatchesGolden(background, list, name);
}

// A checkerboard of 8-pixel squares, so that blending shows.
void drawCheckerboard(Canvas& canvas);

// The sprite the golden tests draw: 20×14 pixels, an arrow pointing right (+x) with a yellow
// stripe on its upper edge (so mirroring shows), an opaque gradient body, translucent exhaust at its
// tail and transparent corners.
Image makeArrowSprite();

}  // namespace polar::render::testing
