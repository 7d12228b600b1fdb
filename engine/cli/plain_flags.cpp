#include "plain_flags.h"

namespace polar::cli {

void PlainFlags::add(std::string name, bool takesValue, Take take) {
    entries_.push_back({std::move(name), takesValue, std::move(take)});
}

void PlainFlags::flag(std::string name, bool& target) {
    add(std::move(name), false, [&target](std::string_view, std::string&) {
        target = true;
        return true;
    });
}

void PlainFlags::text(std::string name, std::string& target) {
    add(std::move(name), true, [&target](std::string_view value, std::string&) {
        target = std::string(value);
        return true;
    });
}

std::optional<std::string> PlainFlags::parse(const std::vector<std::string>& args) const {
    for (std::size_t i = 0; i < args.size(); ++i) {
        const Entry* entry = nullptr;
        for (const Entry& e : entries_)
            if (e.name == args[i]) entry = &e;
        if (!entry) {
            std::string known;
            for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
            return "unknown flag " + args[i] + "; expected one of " + known;
        }
        std::string_view value;
        if (entry->takesValue) {
            if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0)
                return entry->name + ": expected a value";
            value = args[++i];
        }
        std::string problem;
        if (!entry->take(value, problem)) return entry->name + ": " + problem;
    }
    return std::nullopt;
}

}  // namespace polar::cli
