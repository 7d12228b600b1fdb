#include "app/input/data_folder.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "polar/platform/system.h"

namespace polar::game {

namespace fs = std::filesystem;

DataFolder openDataFolder(const std::string& asked) {
    const char* expected = "a writable folder (choose one with --data DIR or POLARCADE_DATA)";
    DataFolder data;
    std::string chosen = asked;
    if (const char* env = std::getenv(kDataFolderVariable); chosen.empty() && env && *env) chosen = env;
    if (chosen.empty()) {
        Result<std::string> pref = platform::userDataFolder("polarcade", "polarcade");
        if (!pref) {
            data.problem = pref.error();
            data.problem->expected = expected;
            return data;
        }
        chosen = *pref;
    }
    if (chosen.back() != '/') chosen += '/';
    data.path = chosen;
    std::error_code ec;
    const std::string bare =
        chosen.size() > 1 ? chosen.substr(0, chosen.size() - 1) : chosen;  // "x/" is never a file
    if (fs::exists(bare, ec) && !fs::is_directory(bare, ec)) {
        data.problem = Error{chosen, 0, 0, "the data folder is a file, not a folder", expected};
        return data;
    }
    fs::create_directories(chosen, ec);
    if (ec || !fs::is_directory(chosen, ec)) {
        data.problem =
            Error{chosen, 0, 0,
                  "the data folder cannot be created: " + (ec ? ec.message() : std::string("not a folder")),
                  expected};
        return data;
    }
    const std::string probe = chosen + ".polarcade-write-test";
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (!file || std::fclose(file) != 0) {
        data.problem =
            Error{chosen, 0, 0, std::string("the data folder cannot be written: ") + std::strerror(errno),
                  expected};
        return data;
    }
    std::remove(probe.c_str());
    return data;
}

}  // namespace polar::game
