// The snapshot frame both snapshots share (the world's and the game's): its bytes are magic,
// version, the payload's size and its checksum, then the payload; a frame cut short, of another
// kind or version, or damaged is refused with an Error that names the kind.
#include "polar/snapshot_bytes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "polar/world.h"
#include "polar/world_snapshot.h"

namespace polar {
namespace {

constexpr SnapshotKind kTest{0x54534554, 3, "test snapshot", "the test"};

std::vector<std::uint8_t> framed(std::uint64_t a, std::string_view text) {
    std::vector<std::uint8_t> bytes;
    ByteWriter w = startSnapshotFrame(bytes, kTest);
    w.put(a);
    w.text(text);
    endSnapshotFrame(w);
    return bytes;
}

template <class T>
T at(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

TEST(SnapshotFrame, HoldsMagicVersionSizeAndChecksumThenThePayload) {
    std::vector<std::uint8_t> bytes = framed(42, "rock");
    std::size_t payload = 8 + 4 + 4;
    ASSERT_EQ(bytes.size(), kSnapshotHeaderBytes + payload);
    EXPECT_EQ(at<std::uint32_t>(bytes, 0), kTest.magic);
    EXPECT_EQ(at<std::uint32_t>(bytes, 4), kTest.version);
    EXPECT_EQ(at<std::uint64_t>(bytes, 8), payload);
    EXPECT_EQ(at<std::uint64_t>(bytes, 16), snapshotChecksum(bytes.data() + kSnapshotHeaderBytes, payload));

    Result<ByteReader> in = openSnapshotFrame(bytes, kTest);
    ASSERT_TRUE(in) << in.error().message();
    EXPECT_EQ(in->get<std::uint64_t>(), 42u);
    EXPECT_EQ(in->text(), "rock");
    EXPECT_TRUE(in->ok());
    EXPECT_EQ(in->left(), 0u);
}

TEST(SnapshotFrame, AWarmBufferIsCutToTheNewFrame) {
    std::vector<std::uint8_t> bytes = framed(1, std::string(500, 'x'));
    ByteWriter w = startSnapshotFrame(bytes, kTest);
    w.put(std::uint64_t{7});
    endSnapshotFrame(w);
    EXPECT_EQ(bytes.size(), kSnapshotHeaderBytes + 8);
    ASSERT_TRUE(openSnapshotFrame(bytes, kTest));
}

TEST(SnapshotFrame, RefusesWhatIsNotItsOwnWhole) {
    const std::vector<std::uint8_t> good = framed(42, "rock");
    auto refusal = [](const std::vector<std::uint8_t>& bytes) {
        Result<ByteReader> in = openSnapshotFrame(bytes, kTest);
        return in ? std::string("accepted") : in.error().message();
    };
    auto startsWith = [](const std::string& message, const std::string& what) {
        return message.rfind("test snapshot: " + what, 0) == 0;
    };

    std::vector<std::uint8_t> bytes(good.begin(), good.begin() + 10);
    EXPECT_PRED2(startsWith, refusal(bytes), "cut off in the header (10 bytes)");
    bytes = good;
    bytes[0] ^= 1;
    EXPECT_PRED2(startsWith, refusal(bytes), "not a test snapshot");
    bytes = good;
    bytes[4] = 9;
    EXPECT_PRED2(startsWith, refusal(bytes), "version 9");
    bytes = good;
    bytes.pop_back();
    EXPECT_PRED2(startsWith, refusal(bytes), "cut off: 15 bytes of a state of 16");
    bytes = good;
    bytes.back() ^= 0x40;
    EXPECT_PRED2(startsWith, refusal(bytes), "damaged: the checksum does not match");
    EXPECT_NE(refusal(bytes).find("expected a buffer written by the test, version 3"), std::string::npos)
        << refusal(bytes);
}

TEST(SnapshotFrame, IsTheFrameOfAWorldSnapshot) {
    WorldSnapshot snapshot;
    saveSnapshot(World(), snapshot);
    SnapshotKind world{at<std::uint32_t>(snapshot.bytes, 0), kWorldSnapshotVersion, "world snapshot",
                       "saveSnapshot"};
    Result<ByteReader> in = openSnapshotFrame(snapshot.bytes, world);
    ASSERT_TRUE(in) << in.error().message();
    EXPECT_EQ(in->left(), snapshot.bytes.size() - kSnapshotHeaderBytes);
    EXPECT_EQ(at<std::uint32_t>(snapshot.bytes, 0), 0x504e5350u);  // "PSNP", as every saved world has it
}

}  // namespace
}  // namespace polar
