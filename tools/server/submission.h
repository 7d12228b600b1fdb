#pragma once
// A submission as it arrives: the JSON body of POST /v1/runs, read and checked field by field
// before anything else looks at it.
#include <string>
#include <string_view>

#include "polar/error.h"

namespace polar::server {

inline constexpr std::size_t kMaxNameCharacters = 24;

// What a client sends: the replay text, who signs it and the run token it started with.
struct Submission {
    std::string name;
    std::string publicKey;  // raw 32 bytes (hexadecimal in the body)
    std::string signature;  // raw 64 bytes (hexadecimal in the body)
    std::string token;      // hexadecimal as issued; empty for a run without one
    std::string replay;     // the replay file's bytes
};

// Reads a body; an Error naming the field (or the line and column of broken JSON) and what is
// expected. Never throws, whatever the bytes.
Result<Submission> parseSubmission(std::string_view body);

// What is wrong with a player name ("" when it is fine): 1 to kMaxNameCharacters characters of
// UTF-8, none a control or direction-override character, no space at either end.
std::string nameProblem(std::string_view name);

// Whether `token` looks like one the server issues (32 hexadecimal digits).
bool tokenWellFormed(std::string_view token);

}  // namespace polar::server
