#include "app/hot_reload_hud.h"

#include <algorithm>

#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {

using render::Color;

namespace {

constexpr Color kProblemBox{70, 8, 14, 225};
constexpr Color kProblemTitle{255, 200, 120, 255};
constexpr Color kProblemText{255, 170, 170, 255};
constexpr Color kNoticeText{140, 255, 160, 255};
constexpr std::uint64_t kNoticeCalls = 150;  // about 2.5 s at one update per frame
constexpr int kBottomGap = 16;               // room for the debug overlay's line

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

void drawHotReloadStatus(render::Canvas& canvas, const HotReload& reload) {
    const int margin = 6;
    const std::size_t columns =
        static_cast<std::size_t>((canvas.width() - 2 * margin - 4) / render::kCharAdvance);
    int bottom = canvas.height() - kBottomGap;
    if (!reload.problems().empty()) {
        std::vector<std::string> lines{
            "NOT RELOADED - THE GAME KEEPS THE LAST GOOD VERSION UNTIL THE FILE IS FIXED:"};
        for (const auto& [path, error] : reload.problems())
            for (std::string& line : wrapText(error.message(), columns)) lines.push_back(std::move(line));
        const std::size_t most = 8;  // never cover the whole screen
        if (lines.size() > most) {
            lines.resize(most);
            lines.back() = "... (the rest is on stderr)";
        }
        int height = static_cast<int>(lines.size()) * render::kLineHeight + 6;
        int top = bottom - height;
        render::fillRect(canvas, margin - 2, top, canvas.width() - 2 * (margin - 2), height, kProblemBox);
        for (std::size_t i = 0; i < lines.size(); ++i)
            render::drawText(canvas, lines[i], margin + 2,
                             top + 3 + static_cast<int>(i) * render::kLineHeight, 1,
                             i == 0 ? kProblemTitle : kProblemText);
        bottom = top - 2;
    }
    if (!reload.notice().empty() && reload.noticeAge() < kNoticeCalls) {
        std::vector<std::string> lines = wrapText(reload.notice(), columns);
        int top = bottom - static_cast<int>(lines.size()) * render::kLineHeight - 2;
        render::fillRect(canvas, margin - 2, top - 2, canvas.width() - 2 * (margin - 2),
                         static_cast<int>(lines.size()) * render::kLineHeight + 4, Color{0, 0, 0, 150});
        for (std::size_t i = 0; i < lines.size(); ++i)
            render::drawText(canvas, lines[i], margin + 2, top + static_cast<int>(i) * render::kLineHeight, 1,
                             kNoticeText);
    }
}

}  // namespace polar::game
