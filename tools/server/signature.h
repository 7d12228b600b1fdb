#pragma once
// Ed25519 identities (libsodium): what a submission signs, and checking it.
//
// Why keys and no passwords? A player's game makes a key pair once and keeps it; the name belongs
// to the first key that signs a run with it. The server never holds a secret, so a leak of its
// database gives nobody a way to post as a player.
#include <optional>
#include <string>
#include <string_view>

namespace polar::server {

// Bytes as lower-case hexadecimal, and back (nothing for text that is not an even run of hex digits).
std::string toHex(std::string_view bytes);
std::optional<std::string> fromHex(std::string_view hex);

// SHA-256 of `bytes`, in hexadecimal: the replay hash that is signed.
std::string sha256Hex(std::string_view bytes);

// The message a submission's signature covers: the name, the replay's hash and the run token (""
// when there is none), each on its own line after a line naming this format.
std::string signedMessage(const std::string& name, const std::string& replayHash, const std::string& token);

// An Ed25519 key pair; both parts raw bytes (32 and 64).
struct KeyPair {
    std::string publicKey;
    std::string secretKey;
};
KeyPair generateKeyPair();
// The public key held in a secret key (its last 32 bytes).
std::string publicKeyOf(const std::string& secretKey);
// The detached signature of `message` (64 raw bytes).
std::string sign(const std::string& secretKey, std::string_view message);
// Whether `signature` (raw) is `publicKey`'s (raw) over `message`.
bool signatureValid(const std::string& publicKey, const std::string& signature, std::string_view message);

}  // namespace polar::server
