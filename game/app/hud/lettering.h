#pragma once
#include <string>

#include "polar/render/color.h"

namespace polar::game {

// How the game letters its words: the colours text is drawn in, each named once, and names in
// capitals. The screens, the overlays and the theatre all draw from here, so a colour is changed
// in one place.
inline constexpr render::Color kGold{255, 214, 120, 255};       // headings, the focused entry, notices
inline constexpr render::Color kTextColor{220, 228, 255, 255};  // a screen's words
inline constexpr render::Color kDimColor{150, 160, 200, 255};   // help lines, what is not chosen
inline constexpr render::Color kWarnColor{255, 120, 110, 255};  // what went wrong
inline constexpr render::Color kHudText{230, 236, 255, 255};    // the score line and the panels
inline constexpr render::Color kHudDim{140, 150, 190, 255};     // the HUD's quieter words

// `text` in capitals, as the screens write names ("cave" → "CAVE").
std::string upperCase(std::string text);

}  // namespace polar::game
