#pragma once
// Files a flag names for a program to write (a replay, a report, a CSV table), checked as the
// command line is read: a run that would end unable to save what it made is refused before it
// starts, and leaves nothing behind.
#include <string>

namespace polar::cli {

// Why `path` cannot be written as a file ("" when it can): it names a folder, or its folder does
// not exist, is not a folder, or cannot be written. The words continue "PATH: ", and a message
// ends them with "; expected a file in a writable folder".
std::string outputFileProblem(const std::string& path);

}  // namespace polar::cli
