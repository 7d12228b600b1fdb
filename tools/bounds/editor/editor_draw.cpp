// The editor's picture: the sprite zoomed in whole pixels, the outlines exactly as the collision
// rule sees them (boundOutline), handles, the partner, and a panel with gen's and check's report.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bounds_drawing.h"
#include "editor/editor.h"
#include "polar/bound_outline.h"
#include "polar/render/render.h"

namespace polar::bounds_tool::editor {
namespace {

constexpr Color kPanel{16, 17, 26, 255};
constexpr Color kBar{14, 15, 22, 255};
constexpr Color kProblem{255, 110, 100, 255};
constexpr Color kWarning{255, 190, 90, 255};
constexpr Color kGood{120, 230, 140, 255};
constexpr Color kPartnerOutline{200, 200, 215, 255};
constexpr Color kOverlap{255, 60, 200, 150};  // opaque pixels that overlap the other sprite's

constexpr int kPanelX = Editor::kDrawingWidth + 8;
constexpr int kPanelChars = (Editor::kWidth - kPanelX - 6) / render::kCharAdvance;

// `text` broken into lines of at most `width` characters, at spaces where it can.
std::vector<std::string> wrap(const std::string& text, std::size_t width, const std::string& indent = "  ") {
    std::vector<std::string> lines;
    std::string rest = text;
    std::string lead;
    while (lead.size() + rest.size() > width) {
        const std::size_t room = width - lead.size();
        std::size_t cut = rest.rfind(' ', room);
        if (cut == std::string::npos || cut == 0) cut = room;
        lines.push_back(lead + rest.substr(0, cut));
        rest = rest.substr(cut + (cut < rest.size() && rest[cut] == ' ' ? 1 : 0));
        lead = indent;
    }
    lines.push_back(lead + rest);
    return lines;
}

std::string fixed(double v, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

void drawCross(render::Canvas& canvas, const Vec2& p, Color color, double size) {
    render::drawLine(canvas, p - Vec2(size, 0), p + Vec2(size, 0), color);
    render::drawLine(canvas, p - Vec2(0, size), p + Vec2(0, size), color);
}

// The pixel square of bound-space centre c (a unit square) under m, filled.
void fillPixel(render::Canvas& canvas, const Mat3& m, const Vec2& c, Color color) {
    const Vec2 corners[4] = {
        render::transformPoint(m, c + Vec2(-0.5, -0.5)), render::transformPoint(m, c + Vec2(0.5, -0.5)),
        render::transformPoint(m, c + Vec2(0.5, 0.5)), render::transformPoint(m, c + Vec2(-0.5, 0.5))};
    render::fillPolygon(canvas, corners, color);
}

}  // namespace

void Editor::draw(render::Canvas& canvas) const {
    canvas.clear(kBackground);
    // The drawing clips at its own edges: a canvas over the same pixels.
    const int areaHeight = kHeight - kTop - kBottom;
    render::Canvas scene = render::Canvas::wrap(canvas.row(kTop), kDrawingWidth, areaHeight, canvas.pitch());
    drawScene(scene);
    drawPanel(canvas);

    // The message bar: what was just done, or what went wrong.
    render::fillRect(canvas, 0, 0, kWidth, kTop, kBar);
    const std::string message = message_.empty() ? "ready" : message_;
    std::vector<std::string> lines = wrap(message, (kWidth - 8) / render::kCharAdvance);
    render::drawText(canvas, lines.front() + (lines.size() > 1 ? " ..." : ""), 4, 2, 1,
                     messageIsProblem_ ? kProblem : kDimText);

    // The help line.
    render::fillRect(canvas, 0, kHeight - kBottom, kWidth, kBottom, kBar);
    render::drawText(
        canvas,
        "drag handle: move sample  click outline: add  Del: remove  Tab: radii  N/X: add/remove radii  "
        "I: interpolate",
        4, kHeight - kBottom + 3, 1, kDimText);
    render::drawText(canvas,
                     "F: fit  T: tighten  P: partner  1-6: accuracy  wheel: zoom  middle/space drag: pan  "
                     "Ctrl+Z/Y: undo/redo  Ctrl+S: save  H: keys",
                     4, kHeight - kBottom + 13, 1, kDimText);

    if (showKeys_) {
        const std::vector<std::string>& keys = editorKeys();
        const int w = 76 * render::kCharAdvance + 16,
                  h = static_cast<int>(keys.size()) * render::kLineHeight + 30;
        const int x = (kDrawingWidth - w) / 2, y = kTop + 20;
        render::fillRect(canvas, x, y, w, h, Color{10, 11, 18, 235});
        render::drawRect(canvas, x, y, w, h, kAxes);
        render::drawText(canvas, "KEYS (H or Esc closes)", x + 8, y + 8, 1, kText);
        for (std::size_t i = 0; i < keys.size(); ++i)
            render::drawText(canvas, keys[i], x + 8, y + 22 + static_cast<int>(i) * render::kLineHeight, 1,
                             kDimText);
    }
    if (asking_) {
        const int w = 420, h = 52, x = (kDrawingWidth - w) / 2, y = kTop + areaHeight / 2 - h / 2;
        render::fillRect(canvas, x, y, w, h, Color{30, 12, 14, 245});
        render::drawRect(canvas, x, y, w, h, kProblem);
        render::drawText(
            canvas, "Unsaved changes to " + setup_.boundsPath.substr(setup_.boundsPath.find_last_of('/') + 1),
            x + 10, y + 10, 1, kText);
        render::drawText(canvas, "S: save and quit   D: discard and quit   Esc: keep editing", x + 10, y + 30,
                         1, kWarning);
    }
}

void Editor::drawScene(render::Canvas& scene) const {
    // The scene canvas starts kTop rows down: shift every canvas point by that.
    Mat3 shift = Mat3::Identity();
    shift(1, 2) = -kTop;
    const Mat3 m = shift * matrix();
    const double w = setup_.sprite.mask.width, h = setup_.sprite.mask.height;
    auto at = [&](const Vec2& p) { return render::transformPoint(m, p); };

    // The image's rectangle and, when it is large enough, its pixel grid.
    const Vec2 topLeft = at(Vec2(-w / 2, h / 2));
    render::fillRect(scene, static_cast<int>(topLeft.x()), static_cast<int>(topLeft.y()),
                     static_cast<int>(w * zoom_), static_cast<int>(h * zoom_), kImageArea);
    if (zoom_ >= 6) {
        for (int i = 0; i <= w; ++i)
            render::drawLine(scene, at(Vec2(i - w / 2, -h / 2)), at(Vec2(i - w / 2, h / 2)), kPixelGrid);
        for (int j = 0; j <= h; ++j)
            render::drawLine(scene, at(Vec2(-w / 2, j - h / 2)), at(Vec2(w / 2, j - h / 2)), kPixelGrid);
    }
    render::drawSprite(scene, setup_.image, m);

    // The sprite's own axes through its centre.
    const Vec2 o = at(Vec2::Zero());
    const double reach = std::max(w, h) / 2 + 6.0 / zoom_ + 4;
    render::drawLine(scene, at(Vec2(-reach, 0)), o, kAxes.withAlpha(140));
    render::drawLine(scene, at(Vec2(0, -reach)), o, kAxes.withAlpha(140));
    drawArrow(scene, o, at(Vec2(reach, 0)), kAxes);
    drawArrow(scene, o, at(Vec2(0, reach)), kAxes);
    render::drawText(scene, "+x", static_cast<int>(at(Vec2(reach, 0)).x()) + 6, static_cast<int>(o.y()) - 4,
                     1, kAxes);
    render::drawText(scene, "+y", static_cast<int>(o.x()) - 5, static_cast<int>(at(Vec2(0, reach)).y()) - 14,
                     1, kAxes);

    // The partner: its sprite, its outline (by its own file's rule), and the overlapping pixels.
    if (partner_ > 0) {
        const Partner& p = setup_.partners[partner_ - 1];
        const Mat3 pm = m * partnerPlace_.matrix();
        render::drawSprite(scene, p.image, pm, render::SpriteStyle{render::kWhite, 220});
        const Bounds& pb = p.bounds ? *p.bounds : *model_.bounds();
        for (const Bound& r : pb)
            render::drawPolygon(scene, boundOutline(r, pm), kPartnerOutline.withAlpha(200));
        drawCross(scene, render::transformPoint(pm, Vec2::Zero()), kPartnerOutline, 3);
        for (const Vec2& c : overlapOwn_) fillPixel(scene, m, c, kOverlap);
        for (const Vec2& c : overlapPartner_) fillPixel(scene, pm, c, kOverlap);
    }

    // Each bound: spokes, outline, handles, centre. The selected one last, on top, at full colour.
    const Bounds& bounds = *model_.bounds();
    const BoundsSpec& spec = model_.spec();
    for (std::size_t n = 1; n <= spec.radii.size(); ++n) {
        const std::size_t k = (radii_ + n) % spec.radii.size();
        const bool selected = k == radii_;
        const Color color = kRadiiColors[k % std::size(kRadiiColors)];
        const BoundSpec& r = spec.radii[k];
        const Vec2 centre = at(r.centre);
        std::vector<Vec2> tips;
        for (const DegreeSample& s : r.samples) {
            double sn = 0, cs = 0;
            trig::sincos(degToRad(reduceDegrees(s[0])), sn, cs);
            tips.push_back(at(r.centre + s[1] * Vec2(cs, sn)));
        }
        for (const Vec2& t : tips) render::drawLine(scene, centre, t, color.withAlpha(selected ? 110 : 60));
        render::drawPolygon(scene, boundOutline(bounds[k], m), selected ? color : color.withAlpha(150));
        for (std::size_t j = 0; j < tips.size(); ++j) {
            const int x = static_cast<int>(std::floor(tips[j].x())),
                      y = static_cast<int>(std::floor(tips[j].y()));
            const bool chosen = selected && sample_ && *sample_ == j;
            if (chosen) {
                render::fillRect(scene, x - 3, y - 3, 7, 7, color);
                render::drawRect(scene, x - 4, y - 4, 9, 9, kText);
            } else {
                render::fillRect(scene, x - 1, y - 1, 3, 3, selected ? kText : kDimText);
            }
        }
        drawCross(scene, centre, color, selected ? 6 : 4);
        render::drawCircle(scene, centre, selected ? 4 : 3, color);
        if (spec.radii.size() > 1)
            render::drawText(scene, "C" + std::to_string(k + 1), static_cast<int>(centre.x()) + 7,
                             static_cast<int>(centre.y()) + 5, 1, color);
        // The chosen sample's angle and radius as the file writes them, past its tip.
        if (selected && sample_) {
            const DegreeSample& s = r.samples[*sample_];
            const Vec2 tip = tips[*sample_];
            const Vec2 out =
                (tip - centre).norm() > 0 ? Vec2((tip - centre).normalized()) : Vec2(Vec2::UnitX());
            const std::string text = fixed(s[0], 1) + " deg, r " + fixed(s[1], 3);
            const render::TextSize ts = render::measureText(text, 1);
            const Vec2 p = tip + out * (12 + 0.5 * std::fabs(out.x()) * ts.width);
            const int x = static_cast<int>(std::lround(p.x() - ts.width / 2.0)),
                      y = static_cast<int>(p.y()) - 4;
            render::fillRect(scene, x - 2, y - 2, ts.width + 4, 13, kBar.withAlpha(200));
            render::drawText(scene, text, x, y, 1, kText);
        }
    }
}

void Editor::drawPanel(render::Canvas& canvas) const {
    render::fillRect(canvas, kDrawingWidth, kTop, kWidth - kDrawingWidth, kHeight - kTop - kBottom, kPanel);
    int y = kTop + 6;
    auto line = [&](const std::string& text, Color color) {
        for (const std::string& l : wrap(text, kPanelChars)) {
            if (y > kHeight - kBottom - 112) return;  // keep the compass clear
            render::drawText(canvas, l, kPanelX, y, 1, color);
            y += render::kLineHeight;
        }
    };
    const std::string file = setup_.boundsPath.substr(setup_.boundsPath.find_last_of('/') + 1);
    line(file + (model_.dirty() ? "  (unsaved)" : "  (saved)"), model_.dirty() ? kWarning : kText);
    if (!setup_.loadProblem.empty()) line("not loaded: " + setup_.loadProblem, kProblem);
    line("zoom " + std::to_string(zoom_) + "x" + (setup_.sprite.container ? ", container" : ""), kDimText);
    y += 4;
    line("FIT (as gen prints it)", kText);
    const BoundsSpec& spec = model_.spec();
    for (std::size_t k = 0; k < spec.radii.size() && k < report_.lines.size(); ++k) {
        const Color color = kRadiiColors[k % std::size(kRadiiColors)];
        const std::string mark = k == radii_ ? "> " : "  ";
        line(mark + report_.lines[k] + ", interpolate " + (spec.radii[k].interpolate ? "true" : "false"),
             k == radii_ ? color : color.withAlpha(170));
    }
    y += 4;
    line(report_.warnings.empty() ? "CHECK: no warnings"
                                  : "CHECK: " + std::to_string(report_.warnings.size()) + " warning" +
                                        (report_.warnings.size() == 1 ? "" : "s"),
         report_.warnings.empty() ? kGood : kWarning);
    for (std::size_t i = 0; i < report_.warnings.size() && i < 4; ++i) {
        const std::string& w = report_.warnings[i];
        line(w.substr(w.find_last_of('/') == std::string::npos ? 0 : w.find_last_of('/') + 1), kWarning);
    }
    if (report_.warnings.size() > 4)
        line("... and " + std::to_string(report_.warnings.size() - 4) + " more", kWarning);
    y += 4;
    if (partner_ == 0) {
        line("PARTNER: none (P chooses one)", kText);
    } else {
        const Partner& p = setup_.partners[partner_ - 1];
        line("PARTNER: " + p.name, kText);
        const Vec2 s = partnerPlace_.scaleFactors();
        line("at (" + fixed(partnerPlace_.position().x(), 2) + ", " + fixed(partnerPlace_.position().y(), 2) +
                 "), turned " + fixed(radToDeg(partnerPlace_.rotation()), 1) + " deg, scale " +
                 fixed(s.x(), 2),
             kDimText);
        line(std::string("rule (") + accuracyName(accuracy_) + "): " + (ruleHit_ ? "HIT" : "miss"),
             ruleHit_ ? kProblem : kGood);
        line(std::string("pixels: ") + (pixelsHit_ ? "HIT" : "miss") +
                 (overlapSkipped_ ? " (too many pixels to mark them)"
                                  : " (" + std::to_string(overlapOwn_.size() + overlapPartner_.size()) +
                                        " overlapping px shown)"),
             pixelsHit_ ? kProblem : kGood);
        if (ruleHit_ != pixelsHit_)
            line(ruleHit_ ? "the outlines touch where the pixels do not"
                          : "the pixels touch where the outlines do not",
                 kWarning);
    }
    // The angle convention.
    const int top = kHeight - kBottom - 106;
    drawCompass(canvas, Vec2(kDrawingWidth + 60, top + 52));
    int ty = top + 30;
    for (const char* text : {"degrees, counter-", "clockwise from +x", "(x right, y up)"}) {
        render::drawText(canvas, text, kDrawingWidth + 128, ty, 1, kDimText);
        ty += render::kLineHeight;
    }
}

}  // namespace polar::bounds_tool::editor
