#include "submission.h"

#include "polar/json_doc.h"

#include "signature.h"

namespace polar::server {
namespace {

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
    constexpr const char* kExpected =
        "a JSON object with name, public_key, signature, replay and maybe token";
    Result<JsonDoc> doc = JsonDoc::parse(SourceFile{"request body", std::string(text)});
    if (!doc) return doc.error();
    Submission s;
    try {
        const JsonNode body = doc->root();
        if (!body.isObject()) body.fail("not a JSON object", kExpected);
        body.allowKeys({"name", "public_key", "signature", "token", "replay"});
        const JsonNode name = body.require("name", "the player's name as a string");
        s.name = name.string("the player's name as a string");
        if (std::string problem = nameProblem(s.name); !problem.empty())
            name.fail(problem, "1 to " + std::to_string(kMaxNameCharacters) +
                                   " printable characters with no space at either end");
        const JsonNode key = body.require("public_key", "64 hexadecimal digits");
        std::optional<std::string> keyBytes = fromHex(key.string("64 hexadecimal digits"));
        if (!keyBytes || keyBytes->size() != 32)
            key.fail("not an Ed25519 public key", "64 hexadecimal digits");
        s.publicKey = std::move(*keyBytes);
        const JsonNode signature = body.require("signature", "128 hexadecimal digits");
        std::optional<std::string> signatureBytes = fromHex(signature.string("128 hexadecimal digits"));
        if (!signatureBytes || signatureBytes->size() != 64)
            signature.fail("not an Ed25519 signature", "128 hexadecimal digits");
        s.signature = std::move(*signatureBytes);
        if (std::optional<JsonNode> token = body.find("token")) {
            s.token = token->string("a run token as POST /v1/tokens gives it");
            if (!tokenWellFormed(s.token))
                token->fail("not a run token", "32 lower-case hexadecimal digits from POST /v1/tokens");
        }
        const JsonNode replay = body.require("replay", "the replay file's text as a string");
        s.replay = replay.string("the replay file's text as a string");
        if (s.replay.empty()) replay.fail("the replay is empty", "the replay file's text");
    } catch (const LoadFailure& failure) {
        return failure.error;
    }
    return s;
}

}  // namespace polar::server
