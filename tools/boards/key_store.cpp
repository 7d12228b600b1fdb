#include "key_store.h"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "polar/atomic_file.h"
#include "signature.h"

namespace polar::boards {

Result<std::string> loadOrMakeKey(const std::string& folder, std::string& note) {
    const std::string path = (std::filesystem::path(folder) / kKeyFile).string();
    struct stat info {};
    if (::stat(path.c_str(), &info) == 0) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        std::string hex = text.str();
        while (!hex.empty() && (hex.back() == '\n' || hex.back() == '\r')) hex.pop_back();
        std::optional<std::string> key = server::fromHex(hex);
        if (!in || !key || key->size() != 64)
            return Error{path, 1, 1, "not an Ed25519 secret key",
                         "128 hexadecimal digits (move the file away to make a new key, and a new identity)"};
        if (info.st_mode & 077) {
            ::chmod(path.c_str(), 0600);
            note = path + ": was readable by others; now readable by its owner only";
        }
        return *key;
    }
    server::KeyPair pair = server::generateKeyPair();
    // The temporary file is made with the process's umask: 077 gives it mode 0600 from its first
    // byte, and the rename keeps it.
    const mode_t old = ::umask(077);
    std::optional<Error> error = writeFileAtomically(path, server::toHex(pair.secretKey) + "\n");
    ::umask(old);
    if (error) return *error;
    note = path + ": a new key pair for this player";
    return pair.secretKey;
}

}  // namespace polar::boards
