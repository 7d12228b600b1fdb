#include "output_file.h"

#include <filesystem>

#if defined(__unix__) || defined(__APPLE__) || defined(__EMSCRIPTEN__)
#include <unistd.h>
#define POLAR_HAVE_ACCESS 1
#endif

namespace polar::cli {

std::string outputFileProblem(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path file(path);
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (path.empty()) return "no file named";
    if (file.filename().empty()) return "it names a folder, not a file";
    if (!fs::exists(folder, ec)) return "the folder " + folder.string() + " does not exist";
    if (!fs::is_directory(folder, ec)) return folder.string() + " is not a folder";
    if (fs::is_directory(file, ec)) return "it is a folder";
#ifdef POLAR_HAVE_ACCESS
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return "the folder " + folder.string() + " cannot be written";
#endif
    return "";
}

}  // namespace polar::cli
