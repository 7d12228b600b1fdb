#pragma once
// The player's Ed25519 key pair in the data folder: made on first use, kept in a file only its
// owner can read, written atomically so a crash never leaves half a key.
#include <string>

#include "polar/error.h"

namespace polar::boards {

// The key file's name in the data folder.
inline constexpr const char* kKeyFile = "online-key";

// The secret key (64 raw bytes) kept in `folder`, made and saved there when there is none. An Error
// for a key file that is damaged or cannot be written; a readable-by-others file is narrowed to
// its owner (and `note` says so).
Result<std::string> loadOrMakeKey(const std::string& folder, std::string& note);

}  // namespace polar::boards
