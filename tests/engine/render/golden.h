#pragma once
// Golden-image checks for the renderer: a canvas must equal a PNG committed under
// tests/render/golden/ pixel for pixel.
//
// To (re)create goldens after an intended change, run the tests with POLAR_UPDATE_GOLDEN=1
// (for example `POLAR_UPDATE_GOLDEN=1 build/bin/polar-render-tests`), look at every PNG that
// changed, and commit them. On a mismatch the test writes NAME.actual.png and NAME.diff.png (the
// golden dimmed, differing pixels magenta) into build/tests/render-failures/ and reports the first
// differing pixel.
#include <string>

#include "polar/render/canvas.h"
#include "polar/render/image.h"

namespace polar::render::testing {

// Compares `actual` with golden/NAME.png (a gtest failure on mismatch), or rewrites the golden when
// POLAR_UPDATE_GOLDEN=1.
void expectMatchesGolden(const Canvas& actual, const std::string& name);

// A checkerboard of 8-pixel squares, so that blending shows.
void drawCheckerboard(Canvas& canvas);

// The sprite the golden tests draw: 20×14 pixels, an arrow pointing right (+x) with a yellow
// stripe on its upper edge (so mirroring shows), an opaque gradient body, translucent exhaust at its
// tail and transparent corners.
Image makeArrowSprite();

}  // namespace polar::render::testing
