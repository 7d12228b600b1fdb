#pragma once
#include <cstdint>
#include <cstring>
#include <string_view>

namespace polar {

// FNV-1a over the exact bytes of what is added: bit-exact, so two states hash alike only when every
// double is identical to the last bit. Used for replay checkpoints and determinism tests.
class StateHash {
  public:
    void addBytes(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value_ ^= bytes[i];
            value_ *= 0x100000001b3ull;
        }
    }
    void add(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        add(bits);
    }
    void add(std::uint64_t v) {
        unsigned char bytes[8];
        for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(v >> (8 * i));  // endian-free
        addBytes(bytes, 8);
    }
    void add(std::uint32_t v) { add(std::uint64_t{v}); }
    void add(int v) { add(static_cast<std::uint64_t>(static_cast<std::int64_t>(v))); }
    void add(std::string_view s) {
        add(std::uint64_t{s.size()});
        addBytes(s.data(), s.size());
    }
    std::uint64_t value() const { return value_; }

  private:
    std::uint64_t value_ = 0xcbf29ce484222325ull;
};

}  // namespace polar
