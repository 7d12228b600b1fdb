#pragma once
// Editor scripts: the events a person would make, written one per line, for tests and headless runs.
#include <string>
#include <variant>
#include <vector>

#include "polar/error.h"
#include "polar/platform/events.h"

namespace polar::bounds_tool::editor {

// Writes the editor's picture to a PNG file (a path relative to the script's folder).
struct Screenshot {
    std::string path;
};

using ScriptStep = std::variant<platform::Event, Screenshot>;

// The steps of a script. One command a line; '#' starts a comment; X Y are canvas pixels (the
// event lands on the pixel's centre, as from a window at scale 1):
//   move X Y                      the pointer moves
//   press BUTTON X Y              BUTTON (left, middle, right) goes down at X Y
//   release BUTTON X Y
//   click BUTTON X Y              press and release
//   drag BUTTON X1 Y1 X2 Y2 [N]   press at X1 Y1, N moves (default 8) to X2 Y2, release
//   wheel DY                      DY notches (> 0 zooms in)
//   key [ctrl+][shift+][alt+]KEY  press and release (KEY as platform::keyName writes it)
//   down KEY, up KEY              press or release alone (e.g. "down space" for space + drag)
//   quit                          the window's close button
//   screenshot FILE.png           write the picture now
// Errors name the script's file, line and column.
Result<std::vector<ScriptStep>> parseScript(const SourceFile& file);

}  // namespace polar::bounds_tool::editor
