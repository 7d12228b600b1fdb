#include "junit_report.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace polar::game {
namespace {

namespace fs = std::filesystem;

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

// The length of the well-formed UTF-8 sequence at `at` (1 to 4), or 0 when it is not one:
// no overlong forms, no surrogates, nothing above U+10FFFF.
std::size_t utf8Length(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    std::size_t length = 0;
    std::uint32_t code = 0, least = 0;
    if (lead < 0x80) return 1;
    if ((lead & 0xE0) == 0xC0)
        length = 2, code = lead & 0x1F, least = 0x80;
    else if ((lead & 0xF0) == 0xE0)
        length = 3, code = lead & 0x0F, least = 0x800;
    else if ((lead & 0xF8) == 0xF0)
        length = 4, code = lead & 0x07, least = 0x10000;
    else
        return 0;
    if (at + length > text.size()) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(at + i) & 0x3F);
    }
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    // U+FFFE and U+FFFF are not XML characters either.
    if (code == 0xFFFE || code == 0xFFFF) return 0;
    return length;
}

std::string seconds(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", value < 0 ? 0.0 : value);
    return buffer;
}

const char* failureType(CheckResult::Status status) {
    switch (status) {
        case CheckResult::kDesynced:
            return "desync";
        case CheckResult::kDamaged:
            return "damaged";
        case CheckResult::kIncomplete:
            return "incomplete";
        default:
            return "screenshot";
    }
}

std::string firstLine(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

std::string attribute(const char* name, const std::string& value) {
    return std::string(" ") + name + "=\"" + xmlEscaped(value) + "\"";
}

}  // namespace

std::string xmlEscaped(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            case '\t':
                out += "&#9;";
                break;
            case '\n':
                out += "&#10;";
                break;
            case '\r':
                out += "&#13;";
                break;
            default: {
                const std::size_t length = utf8Length(text, i);
                if (length == 0 || static_cast<unsigned char>(c) < 0x20) {
                    out += kReplacement;
                    ++i;
                    continue;
                }
                out.append(text, i, length);
                i += length;
                continue;
            }
        }
        ++i;
    }
    return out;
}

std::string junitClassname(const std::string& replayPath) {
    std::string folder = fs::path(replayPath).lexically_normal().parent_path().generic_string();
    while (folder.rfind("./", 0) == 0) folder.erase(0, 2);
    while (!folder.empty() && folder.front() == '/') folder.erase(0, 1);
    if (folder.empty() || folder == ".") return ".";
    for (char& c : folder)
        if (c == '/') c = '.';
    return folder;
}

std::string junitReport(const std::string& suiteName, const std::vector<CheckResult>& results,
                        const std::vector<std::pair<std::string, std::string>>& properties) {
    std::size_t failures = 0, errors = 0;
    double total = 0;
    std::string cases;
    for (const CheckResult& r : results) {
        total += r.seconds;
        cases += "    <testcase" + attribute("classname", junitClassname(r.path)) +
                 attribute("name", fs::path(r.path).filename().string()) + attribute("file", r.path) +
                 attribute("time", seconds(r.seconds));
        std::string inside;
        switch (r.status) {
            case CheckResult::kPassed:
            case CheckResult::kUpdated:
                break;
            case CheckResult::kDesynced:
            case CheckResult::kDamaged:
            case CheckResult::kScreenshotDiffers:
            case CheckResult::kIncomplete: {
                ++failures;
                inside += "      <failure" + attribute("type", failureType(r.status)) +
                          attribute("message", firstLine(r.report)) + ">" + xmlEscaped(r.report) +
                          "</failure>\n";
                break;
            }
            case CheckResult::kUnplayable:
                ++errors;
                inside += "      <error" + attribute("type", "unplayable") +
                          attribute("message", firstLine(r.report)) + ">" + xmlEscaped(r.report) +
                          "</error>\n";
                break;
        }
        std::string out;
        if (r.status == CheckResult::kUpdated) out += "updated from this build\n";
        for (const std::string& note : r.notes) out += "note: " + note + "\n";
        for (const std::string& picture : r.pictures) out += "[[ATTACHMENT|" + picture + "]]\n";
        if (!out.empty()) inside += "      <system-out>" + xmlEscaped(out) + "</system-out>\n";
        cases += inside.empty() ? "/>\n" : ">\n" + inside + "    </testcase>\n";
    }
    const std::string counts = attribute("tests", std::to_string(results.size())) +
                               attribute("failures", std::to_string(failures)) +
                               attribute("errors", std::to_string(errors)) + attribute("skipped", "0") +
                               attribute("time", seconds(total));
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites" + attribute("name", suiteName) + counts + ">\n";
    xml += "  <testsuite" + attribute("name", suiteName) + counts + ">\n";
    if (!properties.empty()) {
        xml += "    <properties>\n";
        for (const auto& [name, value] : properties)
            xml += "      <property" + attribute("name", name) + attribute("value", value) + "/>\n";
        xml += "    </properties>\n";
    }
    xml += cases;
    xml += "  </testsuite>\n</testsuites>\n";
    return xml;
}

}  // namespace polar::game
