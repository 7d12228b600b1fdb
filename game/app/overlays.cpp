#include "app/overlays.h"

#include "app/debug_panel.h"
#include "app/hot_reload_hud.h"
#include "polar/render/text.h"

#include <cstdio>

namespace polar::game {
namespace {

using render::Color;

constexpr Color kBarBacking{0, 0, 0, 140};
constexpr Color kPanelBacking{0, 0, 0, 120};
constexpr Color kPanelText{230, 236, 255, 255};
constexpr Color kPanelDim{140, 150, 190, 255};
constexpr Color kNoticeBacking{60, 40, 0, 200};
constexpr Color kNoticeText{255, 214, 120, 255};

}  // namespace

OverlayLayout drawOverlays(render::Canvas& canvas, const OverlayContent& content) {
    OverlayLayout layout(canvas.width(), canvas.height());
    if (!content.bar.empty())
        drawOverlayText(canvas, layout, Corner::BottomLeft, content.bar, kBarBacking, true);
    if (content.frameTime) {
        char line[48];
        std::snprintf(line, sizeof line, "%.1f MS A FRAME  %.0f FPS",
                      content.fps > 0 ? 1000.0 / content.fps : 0.0, content.fps);
        drawOverlayText(canvas, layout, Corner::TopRight, {{line, kPanelText}}, kPanelBacking);
    }
    if (content.debugWorld && content.effectMs) {
        std::vector<OverlayLine> lines;
        for (std::string& line : debugPanelLines(*content.debugWorld, content.fps, *content.effectMs))
            lines.push_back({std::move(line), kPanelDim});
        lines.back().color = kPanelText;  // the step's numbers, under the effects' times
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, kPanelBacking);
    }
    if (content.reload) drawHotReloadStatus(canvas, layout, *content.reload);
    if (!content.notice.empty()) {
        const std::size_t columns = static_cast<std::size_t>((layout.fullWidth() - 4) / render::kCharAdvance);
        std::vector<OverlayLine> lines;
        for (std::string& line : wrapText(content.notice, columns))
            lines.push_back({std::move(line), kNoticeText});
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, kNoticeBacking, true);
    }
    return layout;
}

}  // namespace polar::game
