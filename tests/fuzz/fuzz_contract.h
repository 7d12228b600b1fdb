#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

#include "polar/error.h"

// What every fuzz target asserts about a rejected input: the loader's one-line message
// "file:line:column: what; expected …", placed inside the file it names.
//
// Why abort rather than assert? The fuzz build is Release (NDEBUG), and libFuzzer treats an abort
// as a crash: it stops, prints the stack and saves the input as a reproducer.
namespace polar::fuzz {

[[noreturn]] inline void broken(const std::string& why, const std::string& message) {
    std::fprintf(stderr, "fuzz contract broken: %s\n  message: %s\n", why.c_str(), message.c_str());
    std::abort();
}

// Checks an Error for a file the loader was given as text: a real path, a position and a message.
inline void checkError(const Error& error, const std::string& text) {
    std::string message = error.message();
    if (error.file.empty()) broken("the error names no file", message);
    if (error.line < 1 || error.column < 1) broken("the error has no line:column", message);
    if (error.what.empty()) broken("the error says nothing", message);
    std::string prefix =
        error.file + ":" + std::to_string(error.line) + ":" + std::to_string(error.column) + ": ";
    if (message.compare(0, prefix.size(), prefix) != 0)
        broken("the message does not start with file:line:column", message);
    if (message.find('\n') != std::string::npos) broken("the message spans more than one line", message);
    // A line past the end of the file would send the user looking for nothing. A file of n
    // newlines has n + 1 lines.
    std::size_t lines = 1;
    for (char c : text) lines += c == '\n';
    if (static_cast<std::size_t>(error.line) > lines)
        broken("the error's line is past the end of the file", message);
}

}  // namespace polar::fuzz
