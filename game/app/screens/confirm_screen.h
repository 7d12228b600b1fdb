#pragma once
#include <functional>
#include <memory>
#include <string>

#include "app/screens/screen.h"

namespace polar::game {

// A question over the screen below (named `name` for observers): No (the focus at first) or back
// returns to that screen; Yes does `yes` and answers with its Next.
std::unique_ptr<Screen> makeConfirmScreen(const char* name, std::string question,
                                          std::function<Next(Session&)> yes);

// "Quit?" over the title: Yes leaves the game.
std::unique_ptr<Screen> makeQuitConfirmScreen();

}  // namespace polar::game
