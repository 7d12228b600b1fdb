#include "polar/accuracy.h"

namespace polar {

const char* accuracyName(Accuracy accuracy) {
    switch (accuracy) {
        case Accuracy::Bounds:
            return "bounds";
        case Accuracy::Circle:
            return "circle";
        case Accuracy::Nearest:
            return "nearest";
        case Accuracy::Chord:
            return "chord";
        case Accuracy::AllRadii:
            return "all-radii";
        case Accuracy::Exact:
            return "exact";
    }
    return "?";
}

std::optional<Accuracy> accuracyFromName(std::string_view name) {
    for (Accuracy a : kAllAccuracies)
        if (name == accuracyName(a)) return a;
    return std::nullopt;
}

std::string accuracyNameList() {
    std::string list;
    for (Accuracy a : kAllAccuracies)
        list += (list.empty() ? "\"" : ", \"") + std::string(accuracyName(a)) + "\"";
    return list;
}

}  // namespace polar
