#pragma once
// The SQLite implementation of Storage: one file, write-ahead log, nothing to set up.
#include <memory>
#include <string>

#include "storage.h"

namespace polar::server {

// Opens (creating) the database file at `path` and migrates it; nothing and `error` set when it
// cannot be opened or holds a newer schema than this server knows.
std::unique_ptr<Storage> openSqliteStorage(const std::string& path, std::string& error);

}  // namespace polar::server
