#pragma once
// The results of a replay run as a JUnit XML report, the format CI systems read test results in.
#include <string>
#include <utility>
#include <vector>

#include "replay_check.h"

namespace polar::game {

// Text made safe for XML 1.0 content and attribute values: & < > " ' as entities, tab, newline and
// carriage return as character references (so attribute values keep them), other control
// characters and bytes that are not UTF-8 as U+FFFD (XML cannot hold them at all).
std::string xmlEscaped(const std::string& text);

// The JUnit classname of a replay: its folder as given, without a leading "/" or "./", with "/" as
// "." ("tests/replays/short.replay" -> "tests.replays"); "." for a file in the current folder.
std::string junitClassname(const std::string& replayPath);

// One <testsuite> named `suiteName` inside <testsuites>: a <testcase> per result (classname from
// the folder, name from the file, its time), a desync, a damaged line, a differing screenshot or a
// missing end line as a <failure> of type desync, damaged, screenshot or incomplete with the
// report's text (which names the actual and diff PNGs), an unplayable replay as an <error>, notes and
// pictures in <system-out> (pictures as [[ATTACHMENT|path]], which GitLab and Jenkins link).
std::string junitReport(const std::string& suiteName, const std::vector<CheckResult>& results,
                        const std::vector<std::pair<std::string, std::string>>& properties);

}  // namespace polar::game
