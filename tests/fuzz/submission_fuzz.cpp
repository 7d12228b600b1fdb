// libFuzzer target: the bytes are the body of POST /v1/runs, read as polarcade-server reads it
// (parseSubmission). A body is refused with one line that starts "request body" and says what is
// expected, or it reads into a submission whose every field holds what the server relies on.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_contract.h"
#include "submission.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string body(reinterpret_cast<const char*>(data), size);
    polar::Result<polar::server::Submission> s = polar::server::parseSubmission(body);
    if (!s) {
        const std::string message = s.error().message();
        if (message.rfind("request body", 0) != 0)
            polar::fuzz::broken("the error does not name the body", message);
        if (message.find('\n') != std::string::npos)
            polar::fuzz::broken("the message spans more than one line", message);
        if (s.error().expected.empty())
            polar::fuzz::broken("the error does not say what is expected", message);
        return 0;
    }
    if (!polar::server::nameProblem(s->name).empty()) polar::fuzz::broken("a bad name was read", s->name);
    if (s->publicKey.size() != 32) polar::fuzz::broken("a public key of another size was read", body);
    if (s->signature.size() != 64) polar::fuzz::broken("a signature of another size was read", body);
    if (!s->token.empty() && !polar::server::tokenWellFormed(s->token))
        polar::fuzz::broken("a bad token was read", s->token);
    if (s->replay.empty()) polar::fuzz::broken("an empty replay was read", body);
    return 0;
}
