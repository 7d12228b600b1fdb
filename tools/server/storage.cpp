#include "storage.h"

#include "sqlite_storage.h"

namespace polar::server {

std::unique_ptr<Storage> openStorage(const std::string& url, std::string& error) {
    constexpr std::string_view kSqlite = "sqlite:";
    if (url.starts_with(kSqlite) && url.size() > kSqlite.size())
        return openSqliteStorage(url.substr(kSqlite.size()), error);
    error = "--db " + url + ": unknown database; expected sqlite:PATH";
    return nullptr;
}

std::string nameKey(const std::string& name) {
    std::string key = name;
    for (char& c : key)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return key;
}

}  // namespace polar::server
