#pragma once
// Runs a built executable the way a user would, from a shell, and captures what it said.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace polar::testing {

struct CommandOutcome {
    int exitCode = -1;  // -1 when the process did not exit normally (a crash)
    std::string out;
    std::string err;
};

// A word quoted for sh: 'it'\''s'.
inline std::string shellQuote(const std::string& word) {
    std::string q = "'";
    for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Writes `text` to `path`, creating its folders first.
inline void writeFile(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

// Runs the shell command `command` (already quoted as needed) in `folder`, capturing stdout and
// stderr through files in a fresh scratch folder.
inline CommandOutcome runShell(const std::string& command, const std::filesystem::path& folder = {}) {
    namespace fs = std::filesystem;
    static int counter = 0;
    fs::path scratch = fs::temp_directory_path() /
                       ("polar-run-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(scratch);
    std::string line = (folder.empty() ? "" : "cd " + shellQuote(folder.string()) + " && ") + command + " >" +
                       shellQuote((scratch / "out").string()) + " 2>" +
                       shellQuote((scratch / "err").string());
    int status = std::system(line.c_str());
    CommandOutcome outcome;
    outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.out = readFile(scratch / "out");
    outcome.err = readFile(scratch / "err");
    fs::remove_all(scratch);
    return outcome;
}

// Runs `executable args...`, each argument quoted.
inline CommandOutcome run(const std::string& executable, const std::vector<std::string>& args,
                          const std::filesystem::path& folder = {}) {
    std::string command = shellQuote(executable);
    for (const std::string& a : args) command += " " + shellQuote(a);
    return runShell(command, folder);
}

}  // namespace polar::testing
