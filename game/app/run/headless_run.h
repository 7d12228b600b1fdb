#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "app/context/app_context.h"

namespace polar::game {

// The exit code of a headless run stopped by SIGINT or SIGTERM (128 + SIGINT, as shells report it)
// after it finished its recording.
inline constexpr int kInterruptedExitCode = 130;

// The attract demo's pilot plays `ticks` ticks of the scene off-screen, no window, no audio
// device: the game recorded as the options say (--record, and with `recordIntoData` the data
// folder's replays/), the --screenshot frames saved (announced on stdout when `announce`).
// SIGINT or SIGTERM stop it between ticks with the recordings finished (kInterruptedExitCode).
// The first --screenshot a run that saves frames after ticks `first` to `last` never reaches, as
// an error that says why the run ends there (`limit`: "--ticks 10"); nothing when all are reached.
// Checked before the run starts, so a CI job never passes without the picture it asked for.
std::optional<Error> screenshotNotReached(const AppOptions& options, std::uint64_t first, std::uint64_t last,
                                          const std::string& limit);

int runHeadless(AppContext& context, const std::string& scenePath, std::int64_t ticks, bool announce,
                bool recordIntoData);

}  // namespace polar::game
