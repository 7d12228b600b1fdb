#pragma once
#include <string>

#include "polar/error.h"

namespace polar::platform {

// The folder where this user's files for `app` belong (on Linux $XDG_DATA_HOME/app/, else
// ~/.local/share/app/), created if missing; it ends with '/'. An Error when there is none.
Result<std::string> userDataFolder(const std::string& organisation, const std::string& app);

}  // namespace polar::platform
