#pragma once
#include <string>
#include <string_view>

#include "polar/error.h"

namespace polar::platform {

// The folder where this user's files for `app` belong (on Linux $XDG_DATA_HOME/app/, else
// ~/.local/share/app/), created if missing; it ends with '/'. An Error when there is none.
Result<std::string> userDataFolder(const std::string& organisation, const std::string& app);

// Hands `bytes` to the user as a file named `name` (an export): on a desktop, written atomically
// into their downloads folder ($XDG_DOWNLOAD_DIR, else ~/Downloads when it is a folder, else the
// home folder), as NAME-2.EXT, NAME-3.EXT … when the name is taken; in a browser, offered as a
// download. Where it went (the file's path, or "the browser's downloads"), or the Error.
Result<std::string> offerFile(const std::string& name, std::string_view bytes);

}  // namespace polar::platform
