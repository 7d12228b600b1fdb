#include "signature.h"

#include <sodium.h>

#include <cassert>

namespace polar::server {
namespace {

void initialise() {
    // sodium_init is safe to call again and from several threads; it fails only without an entropy
    // source, where no key could be made safely.
    [[maybe_unused]] static const int ready = sodium_init();
    assert(ready >= 0);
}

}  // namespace

std::string toHex(std::string_view bytes) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string hex;
    hex.reserve(bytes.size() * 2);
    for (unsigned char c : bytes) {
        hex += kDigits[c >> 4];
        hex += kDigits[c & 15];
    }
    return hex;
}

std::optional<std::string> fromHex(std::string_view hex) {
    if (hex.size() % 2) return std::nullopt;
    auto digit = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string bytes;
    bytes.reserve(hex.size() / 2);
    for (std::size_t i = 0; i < hex.size(); i += 2) {
        int high = digit(hex[i]), low = digit(hex[i + 1]);
        if (high < 0 || low < 0) return std::nullopt;
        bytes += static_cast<char>(high * 16 + low);
    }
    return bytes;
}

std::string sha256Hex(std::string_view bytes) {
    initialise();
    unsigned char digest[crypto_hash_sha256_BYTES];
    crypto_hash_sha256(digest, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    return toHex(std::string_view(reinterpret_cast<const char*>(digest), sizeof digest));
}

std::string signedMessage(const std::string& name, const std::string& replayHash, const std::string& token) {
    return "polarcade-run 1\n" + name + "\n" + replayHash + "\n" + token + "\n";
}

KeyPair generateKeyPair() {
    initialise();
    unsigned char pk[crypto_sign_PUBLICKEYBYTES], sk[crypto_sign_SECRETKEYBYTES];
    crypto_sign_keypair(pk, sk);
    KeyPair pair{std::string(reinterpret_cast<char*>(pk), sizeof pk),
                 std::string(reinterpret_cast<char*>(sk), sizeof sk)};
    sodium_memzero(sk, sizeof sk);
    return pair;
}

std::string publicKeyOf(const std::string& secretKey) {
    assert(secretKey.size() == crypto_sign_SECRETKEYBYTES);
    return secretKey.substr(crypto_sign_SECRETKEYBYTES - crypto_sign_PUBLICKEYBYTES);
}

std::string sign(const std::string& secretKey, std::string_view message) {
    initialise();
    assert(secretKey.size() == crypto_sign_SECRETKEYBYTES);
    unsigned char signature[crypto_sign_BYTES];
    crypto_sign_detached(signature, nullptr, reinterpret_cast<const unsigned char*>(message.data()),
                         message.size(), reinterpret_cast<const unsigned char*>(secretKey.data()));
    return std::string(reinterpret_cast<char*>(signature), sizeof signature);
}

bool signatureValid(const std::string& publicKey, const std::string& signature, std::string_view message) {
    initialise();
    if (publicKey.size() != crypto_sign_PUBLICKEYBYTES || signature.size() != crypto_sign_BYTES) return false;
    return crypto_sign_verify_detached(reinterpret_cast<const unsigned char*>(signature.data()),
                                       reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                                       reinterpret_cast<const unsigned char*>(publicKey.data())) == 0;
}

}  // namespace polar::server
