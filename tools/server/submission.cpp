#include "submission.h"

#include <nlohmann/json.hpp>

#include "signature.h"

namespace polar::server {
namespace {

using nlohmann::json;

Error bodyError(std::string what, std::string expected, int line = 0, int column = 0) {
    return Error{"request body", line, column, std::move(what), std::move(expected)};
}

// The line and column of byte `offset` (1-based) in `text`.
void placeOf(std::string_view text, std::size_t offset, int& line, int& column) {
    line = 1;
    column = 1;
    for (std::size_t i = 0; i + 1 < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

// Decodes one UTF-8 character at `i`; false for a malformed, overlong or surrogate sequence.
bool nextCodePoint(std::string_view s, std::size_t& i, char32_t& cp) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    unsigned char b = byte(i);
    int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + extra >= s.size()) return false;
    cp = extra == 0 ? b : b & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return false;
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr char32_t kSmallest[] = {0, 0x80, 0x800, 0x10000};
    if (cp < kSmallest[extra] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += extra + 1;
    return true;
}

// Characters a name never holds: controls (C0, DEL, C1), line and paragraph separators, and the
// direction overrides and isolates that make a name display as another.
bool forbidden(char32_t cp) {
    return cp < 0x20 || (cp >= 0x7F && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029 ||
           (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069) || cp == 0xFEFF;
}

// A string field of `body`; an Error when it is missing (and required) or not a string.
Result<std::string> field(const json& body, const char* name, const char* expected, bool required = true) {
    auto it = body.find(name);
    if (it == body.end()) {
        if (!required) return std::string();
        return bodyError(std::string("no \"") + name + "\" field", expected);
    }
    if (!it->is_string()) return bodyError(std::string("\"") + name + "\" is not a string", expected);
    return it->get<std::string>();
}

}  // namespace

std::string nameProblem(std::string_view name) {
    if (name.empty()) return "the name is empty";
    std::size_t characters = 0;
    for (std::size_t i = 0; i < name.size(); ++characters) {
        char32_t cp = 0;
        if (!nextCodePoint(name, i, cp)) return "the name is not valid UTF-8";
        if (forbidden(cp)) return "the name holds a control or direction character";
    }
    if (characters > kMaxNameCharacters)
        return "the name is longer than " + std::to_string(kMaxNameCharacters) + " characters";
    if (name.front() == ' ' || name.back() == ' ') return "the name begins or ends with a space";
    return "";
}

bool tokenWellFormed(std::string_view token) {
    if (token.size() != 32) return false;
    for (char c : token)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

Result<Submission> parseSubmission(std::string_view text) {
    json body;
    try {
        body = json::parse(text);
    } catch (const json::parse_error& e) {
        int line = 0, column = 0;
        placeOf(text, e.byte, line, column);
        return bodyError("not JSON", "a JSON object with name, public_key, signature, replay and maybe token",
                         line, column);
    }
    if (!body.is_object())
        return bodyError("not a JSON object",
                         "a JSON object with name, public_key, signature, replay and maybe token");
    Submission s;
    Result<std::string> name = field(body, "name", "the player's name as a string");
    if (!name) return name.error();
    if (std::string problem = nameProblem(*name); !problem.empty())
        return bodyError("\"name\": " + problem, "1 to " + std::to_string(kMaxNameCharacters) +
                                                     " printable characters with no space at either end");
    s.name = std::move(*name);
    Result<std::string> key = field(body, "public_key", "64 hexadecimal digits");
    if (!key) return key.error();
    std::optional<std::string> keyBytes = fromHex(*key);
    if (!keyBytes || keyBytes->size() != 32)
        return bodyError("\"public_key\" is not an Ed25519 public key", "64 hexadecimal digits");
    s.publicKey = std::move(*keyBytes);
    Result<std::string> signature = field(body, "signature", "128 hexadecimal digits");
    if (!signature) return signature.error();
    std::optional<std::string> signatureBytes = fromHex(*signature);
    if (!signatureBytes || signatureBytes->size() != 64)
        return bodyError("\"signature\" is not an Ed25519 signature", "128 hexadecimal digits");
    s.signature = std::move(*signatureBytes);
    Result<std::string> token = field(body, "token", "a run token as POST /v1/tokens gives it", false);
    if (!token) return token.error();
    if (!token->empty() && !tokenWellFormed(*token))
        return bodyError("\"token\" is not a run token",
                         "32 lower-case hexadecimal digits from POST /v1/tokens");
    s.token = std::move(*token);
    Result<std::string> replay = field(body, "replay", "the replay file's text as a string");
    if (!replay) return replay.error();
    if (replay->empty()) return bodyError("\"replay\" is empty", "the replay file's text");
    s.replay = std::move(*replay);
    return s;
}

}  // namespace polar::server
