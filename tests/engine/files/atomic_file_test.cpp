#include "polar/atomic_file.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class AtomicFile : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-atomic"); }
    void TearDown() override { fs::remove_all(folder_); }

    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    static std::string read(const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    static void write(const std::string& p, const std::string& text) {
        std::ofstream(p, std::ios::binary) << text;
    }
    // Every file in the folder, to see that no temporary file is left behind.
    std::vector<std::string> files() const {
        std::vector<std::string> out;
        for (const auto& entry : fs::directory_iterator(folder_))
            out.push_back(entry.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }

    fs::path folder_;
};

TEST_F(AtomicFile, WritesANewFile) {
    EXPECT_FALSE(writeFileAtomically(path("a.json"), "{\"x\": 1}\n"));
    EXPECT_EQ(read(path("a.json")), "{\"x\": 1}\n");
    EXPECT_EQ(files(), std::vector<std::string>{"a.json"});
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
    write(path("a.json"), "old contents that are longer than the new ones");
    EXPECT_FALSE(writeFileAtomically(path("a.json"), "new"));
    EXPECT_EQ(read(path("a.json")), "new");
    EXPECT_EQ(files(), std::vector<std::string>{"a.json"});
}

TEST_F(AtomicFile, KeepsTheOldFileWhenAnyStepFails) {
    const std::string old = "{\"format\": 1, \"radii\": []}\n";
    const std::string replacement(100000, 'x');
    for (AtomicWriteStep step : {AtomicWriteStep::kOpen, AtomicWriteStep::kWrite, AtomicWriteStep::kSync,
                                 AtomicWriteStep::kRename}) {
        write(path("bounds.json"), old);
        int calls = 0;
        std::optional<Error> error =
            writeFileAtomically(path("bounds.json"), replacement, [&](AtomicWriteStep s) {
                ++calls;
                return s == step;  // a full disk at exactly this step
            });
        ASSERT_TRUE(error) << "step " << static_cast<int>(step);
        EXPECT_EQ(error->file, path("bounds.json"));
        EXPECT_NE(error->message().find("simulated"), std::string::npos) << error->message();
        EXPECT_EQ(read(path("bounds.json")), old) << "step " << static_cast<int>(step);
        EXPECT_EQ(files(), std::vector<std::string>{"bounds.json"}) << "a temporary file was left behind";
        EXPECT_EQ(calls, static_cast<int>(step) + 1) << "the steps run in order and stop at the failure";
    }
}

TEST_F(AtomicFile, AFailedFirstWriteLeavesNoFile) {
    std::optional<Error> error = writeFileAtomically(
        path("new.json"), "text", [](AtomicWriteStep s) { return s == AtomicWriteStep::kWrite; });
    ASSERT_TRUE(error);
    EXPECT_TRUE(files().empty());
}

TEST_F(AtomicFile, AMissingFolderIsAnErrorNotACrash) {
    std::optional<Error> error = writeFileAtomically(path("no/such/folder/a.json"), "text");
    ASSERT_TRUE(error);
    EXPECT_EQ(error->file, path("no/such/folder/a.json"));
    EXPECT_NE(error->message().find("cannot create the temporary file"), std::string::npos)
        << error->message();
}

TEST_F(AtomicFile, KeepsTheOldFilesPermissions) {
    write(path("a.json"), "old");
    fs::permissions(path("a.json"), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    EXPECT_FALSE(writeFileAtomically(path("a.json"), "new"));
    EXPECT_EQ(fs::status(path("a.json")).permissions(),
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

}  // namespace
}  // namespace polar
