#pragma once
#include "app/context/app_options.h"
#include "app/run/frame_view.h"

namespace polar::game {

// Runs the game as the options say; returns the process exit code.
int runApp(AppOptions options);

}  // namespace polar::game
