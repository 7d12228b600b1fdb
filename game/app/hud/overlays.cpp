#include "app/hud/overlays.h"

#include "app/hud/debug_panel.h"
#include "app/hud/hot_reload_hud.h"
#include "app/hud/lettering.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"

#include <cstdio>

namespace polar::game {
namespace {

using render::Color;

constexpr Color kBarBacking{0, 0, 0, 140};
constexpr Color kPanelBacking{0, 0, 0, 120};
constexpr Color kNoticeBacking{60, 40, 0, 200};
constexpr Color kMessageBacking{0, 0, 0, 200};

constexpr int kBarPad = 2;

}  // namespace

int helpLineRow(int canvasHeight) {
    return canvasHeight - 40;
}

PixelRect barBox(int canvasWidth, int canvasHeight, std::size_t lines, int controls) {
    OverlayLayout layout(canvasWidth, canvasHeight);
    const int text = lines ? static_cast<int>(lines) * render::kLineHeight - 1 : 0;
    const int gap = lines && controls ? kBarPad : 0;
    return layout.place(Corner::BottomLeft, layout.fullWidth(), controls + gap + text + 2 * kBarPad)
        .value_or(PixelRect{});
}

PixelRect barControlsRect(const PixelRect& box, int controls) {
    return {box.x + kBarPad, box.y + kBarPad, box.width - 2 * kBarPad, controls};
}

OverlayLayout drawOverlays(render::Canvas& canvas, const OverlayContent& content) {
    OverlayLayout layout(canvas.width(), canvas.height());
    if (content.barControls > 0) {
        // The bar with the screen's controls on top: the same box barBox() gives, placed first.
        const PixelRect want =
            barBox(canvas.width(), canvas.height(), content.bar.size(), content.barControls);
        if (std::optional<PixelRect> box = layout.place(Corner::BottomLeft, want.width, want.height)) {
            render::fillRect(canvas, box->x, box->y, box->width, box->height, kBarBacking);
            const PixelRect controls = barControlsRect(*box, content.barControls);
            if (content.drawBarControls) content.drawBarControls(canvas, controls);
            int y = controls.y + controls.height + kBarPad;
            for (const OverlayLine& line : content.bar) {
                render::drawText(canvas, line.text, box->x + kBarPad, y, 1, line.color);
                y += render::kLineHeight;
            }
        }
    } else if (!content.bar.empty()) {
        drawOverlayText(canvas, layout, Corner::BottomLeft, content.bar, kBarBacking, true);
    }
    // The help line where the screens always drew it, in a box one pixel larger than its letters;
    // the message right over it, on a dark backing, so neither is ever drawn over the other.
    std::optional<PixelRect> help;
    if (!content.help.empty()) {
        const render::TextSize size = render::measureText(content.help, 1);
        help = layout.placeCentred(size.width + 2, size.height + 2,
                                   helpLineRow(canvas.height()) + size.height + 1);
        if (help)
            render::drawText(canvas, content.help, (canvas.width() - size.width) / 2, help->y + 1, 1,
                             kDimColor);
    }
    if (content.message) {
        const render::TextSize size = render::measureText(content.message->text, 1);
        const int bottom =
            help ? help->y - OverlayLayout::kGap : helpLineRow(canvas.height()) + size.height + 1;
        if (std::optional<PixelRect> box = layout.placeCentred(size.width + 8, size.height + 4, bottom)) {
            render::fillRect(canvas, box->x, box->y, box->width, box->height, kMessageBacking);
            render::drawText(canvas, content.message->text, box->x + 4, box->y + 2, 1,
                             content.message->color);
        }
    }
    if (content.frameTime) {
        char line[48];
        std::snprintf(line, sizeof line, "%.1f MS A FRAME  %.0f FPS",
                      content.fps > 0 ? 1000.0 / content.fps : 0.0, content.fps);
        drawOverlayText(canvas, layout, Corner::TopRight, {{line, kHudText}}, kPanelBacking);
    }
    if (content.debugWorld && content.effectMs) {
        std::vector<OverlayLine> lines;
        for (std::string& line : debugPanelLines(*content.debugWorld, content.fps, *content.effectMs))
            lines.push_back({std::move(line), kHudDim});
        lines.back().color = kHudText;  // the step's numbers, under the effects' times
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, kPanelBacking);
    }
    if (content.reload) drawHotReloadStatus(canvas, layout, *content.reload);
    if (!content.notice.empty()) {
        const std::size_t columns = static_cast<std::size_t>((layout.fullWidth() - 4) / render::kCharAdvance);
        std::vector<OverlayLine> lines;
        for (std::string& line : wrapText(content.notice, columns)) lines.push_back({std::move(line), kGold});
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, kNoticeBacking, true);
    }
    return layout;
}

}  // namespace polar::game
