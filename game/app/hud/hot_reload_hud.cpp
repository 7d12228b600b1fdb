#include "app/hud/hot_reload_hud.h"

#include <algorithm>

#include "polar/render/text.h"

namespace polar::game {

using render::Color;

namespace {

constexpr Color kProblemBox{70, 8, 14, 225};
constexpr Color kProblemTitle{255, 200, 120, 255};
constexpr Color kProblemText{255, 170, 170, 255};
constexpr Color kNoticeText{140, 255, 160, 255};
constexpr std::uint64_t kNoticeCalls = 150;  // about 2.5 s at one update per frame

}  // namespace

std::vector<std::string> wrapText(const std::string& text, std::size_t width) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    width = std::max<std::size_t>(width, 1);
    while (start < text.size()) {
        if (text.size() - start <= width) {
            lines.push_back(text.substr(start));
            break;
        }
        std::size_t cut = text.rfind(' ', start + width);
        if (cut == std::string::npos || cut <= start) cut = start + width;
        lines.push_back(text.substr(start, cut - start));
        start = cut;
        while (start < text.size() && text[start] == ' ') ++start;
    }
    return lines;
}

void drawHotReloadStatus(render::Canvas& canvas, OverlayLayout& layout, const HotReload& reload) {
    const std::size_t columns = static_cast<std::size_t>((layout.fullWidth() - 4) / render::kCharAdvance);
    if (!reload.problems().empty()) {
        std::vector<OverlayLine> lines{
            {"NOT RELOADED - THE GAME KEEPS THE LAST GOOD VERSION UNTIL THE FILE IS FIXED:", kProblemTitle}};
        for (const auto& [path, error] : reload.problems())
            for (std::string& line : wrapText(error.message(), columns))
                lines.push_back({std::move(line), kProblemText});
        const std::size_t most = 8;  // never cover the whole screen
        if (lines.size() > most) {
            lines.resize(most);
            lines.back().text = "... (the rest is on stderr)";
        }
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, kProblemBox, true);
    }
    if (!reload.notice().empty() && reload.noticeAge() < kNoticeCalls) {
        std::vector<OverlayLine> lines;
        for (std::string& line : wrapText(reload.notice(), columns))
            lines.push_back({std::move(line), kNoticeText});
        drawOverlayText(canvas, layout, Corner::BottomLeft, lines, Color{0, 0, 0, 150}, true);
    }
}

}  // namespace polar::game
