#pragma once
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "polar/error.h"

namespace polar {

// Writes plain values into a growing byte buffer: a snapshot's payload, the world's
// (world_snapshot.h) or a game's own state beside it, inside the frame below. Values are written as their
// bytes in memory (little-endian on every target the engine builds for), so a snapshot is for the program
// that made it, not a file format.
//
// Why write through a position instead of push_back? The buffer keeps its size between saves, so a
// warm save is a run of memcpy calls into memory already held: no growth, no zero fill.
class ByteWriter {
  public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}

    void bytes(const void* data, std::size_t size) {
        if (size == 0) return;
        if (at_ + size > out_.size()) out_.resize(std::max<std::size_t>(2 * out_.size(), at_ + size + 256));
        std::memcpy(out_.data() + at_, data, size);
        at_ += size;
    }
    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&value, sizeof value);
    }
    // A length (u32) and the characters.
    void text(std::string_view s) {
        put(static_cast<std::uint32_t>(s.size()));
        bytes(s.data(), s.size());
    }
    std::size_t size() const { return at_; }
    // Writes `value` at an earlier position (a count or a size known only later).
    template <class T>
    void putAt(std::size_t at, const T& value) {
        std::memcpy(out_.data() + at, &value, sizeof value);
    }
    // Cuts the buffer to what was written, and returns it.
    std::span<std::uint8_t> finish() {
        out_.resize(at_);
        return out_;
    }

  private:
    std::vector<std::uint8_t>& out_;
    std::size_t at_ = 0;
};

// Reads what a ByteWriter wrote, never past the end: a read that does not fit fails, leaves zeros,
// and makes every later read fail too, so a parser checks ok() once at the end (or where a count
// decides how much to allocate).
class ByteReader {
  public:
    ByteReader(const std::uint8_t* data, std::size_t size) : at_(data), end_(data + size) {}

    bool bytes(void* data, std::size_t size) {
        if (size == 0) return ok_;
        if (!ok_ || size > left()) {
            ok_ = false;
            std::memset(data, 0, size);
            return false;
        }
        std::memcpy(data, at_, size);
        at_ += size;
        return true;
    }
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        bytes(&value, sizeof value);
        return value;
    }
    // A text written by ByteWriter::text, as a view into the buffer ("" when it does not fit).
    std::string_view text() {
        auto size = get<std::uint32_t>();
        if (!ok_ || size > left()) {
            ok_ = false;
            return {};
        }
        std::string_view s(reinterpret_cast<const char*>(at_), size);
        at_ += size;
        return s;
    }
    // Whether `count` items of at least `itemBytes` each could still follow: checked before a count
    // read from the buffer sizes anything.
    bool canHold(std::uint64_t count, std::size_t itemBytes) {
        if (ok_ && count <= left() / itemBytes) return true;
        ok_ = false;
        return false;
    }
    // Steps over `size` bytes (fails when they are not all there).
    bool skip(std::size_t size) {
        if (!ok_ || size > left()) return ok_ = false;
        at_ += size;
        return true;
    }
    void fail() { ok_ = false; }
    bool ok() const { return ok_; }
    std::size_t left() const { return static_cast<std::size_t>(end_ - at_); }

  private:
    const std::uint8_t* at_;
    const std::uint8_t* end_;
    bool ok_ = true;
};

// The frame every snapshot shares, the world's and a game's: a header of the kind's magic number (u32),
// its version (u32), the payload's size (u64) and the payload's checksum (u64, snapshotChecksum), then
// the payload. A buffer cut short, of another kind or version, or with a byte changed is refused whole
// before a byte of the payload is read.
//
//     ByteWriter w = startSnapshotFrame(out.bytes, kind);   // writes the header, sizes left blank
//     w.put(…);                                              // the payload
//     endSnapshotFrame(w);                                   // fills in the size and the checksum
//
//     Result<ByteReader> in = openSnapshotFrame(snapshot.bytes, kind);   // the payload, checked
struct SnapshotKind {
    std::uint32_t magic = 0;
    std::uint32_t version = 0;
    std::string_view name;       // in errors, as their file: "world snapshot"
    std::string_view writtenBy;  // in what errors expect: "saveSnapshot"
};

inline constexpr std::size_t kSnapshotHeaderBytes = 4 + 4 + 8 + 8;

// A 64-bit checksum of bytes, eight at a time (a multiply-xorshift mix per word): a cut or a flipped
// bit anywhere changes it. Not cryptographic; it guards against damage, not against an adversary.
std::uint64_t snapshotChecksum(const std::uint8_t* data, std::size_t size);

// Starts a frame of `kind` in `out`, reusing the memory it holds; the payload follows through the writer.
// (Inline, as the end is: a writer whose address never leaves the saving function keeps its position
// in a register through the payload's writes.)
inline ByteWriter startSnapshotFrame(std::vector<std::uint8_t>& out, const SnapshotKind& kind) {
    ByteWriter w(out);
    w.put(kind.magic);
    w.put(kind.version);
    w.put(std::uint64_t{0});  // the payload's size and checksum, once known
    w.put(std::uint64_t{0});
    return w;
}
// Ends the frame `w` was started on: cuts the buffer to what was written, fills in the size and checksum.
inline void endSnapshotFrame(ByteWriter& w) {
    std::span<std::uint8_t> bytes = w.finish();
    std::uint64_t payload = bytes.size() - kSnapshotHeaderBytes;
    w.putAt(8, payload);
    w.putAt(16, snapshotChecksum(bytes.data() + kSnapshotHeaderBytes, payload));
}

// Checks the frame of `bytes` against `kind` and returns a reader over its payload, or the Error that
// says what is wrong (snapshotError's form).
Result<ByteReader> openSnapshotFrame(std::span<const std::uint8_t> bytes, const SnapshotKind& kind);
// An Error about a snapshot of `kind`: file = its name, expected = "a buffer written by …, version N".
Error snapshotError(const SnapshotKind& kind, std::string what);

}  // namespace polar
