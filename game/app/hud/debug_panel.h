#pragma once
#include <array>
#include <string>
#include <vector>

#include "polar/effects.h"
#include "polar/world.h"

namespace polar::game {

// The debug panel's lines (F1), top to bottom: the time per step of each effect the scene runs,
// then the frame rate, threads, objects, pairs tested and hits of the last step. An effect the
// scene does not call for is not run and costs nothing, so it has no line.
std::vector<std::string> debugPanelLines(const World& world, double fps,
                                         const std::array<double, kEffectCount>& effectMs);

}  // namespace polar::game
