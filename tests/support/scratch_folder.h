#pragma once
// A fresh, empty folder for the running test, in the system's temporary folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace polar::testing {

// TMP/PREFIX-TESTNAME-PID, emptied if a previous run left it: the test name keeps parallel ctest
// runs apart, the process id keeps two runs of the same test apart. The fixture removes it.
inline std::filesystem::path freshTestFolder(const std::string& prefix) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path folder =
        std::filesystem::temp_directory_path() /
        (prefix + "-" + info->name() + "-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

}  // namespace polar::testing
