#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// Every setting of settings.json on one list: the volumes and mute (left/right change them),
// fullscreen, scaling, the frame time, a key and a pad button for each action (confirm, then press
// the new one; a conflict is refused on screen with its reason; Esc keeps the old one), and reset
// to defaults. Each change is applied at once and saved.
std::unique_ptr<Screen> makeOptionsScreen();

}  // namespace polar::game
