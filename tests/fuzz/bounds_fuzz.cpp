// libFuzzer target: the bytes are a bounds file's text, loaded as the game loads one (parseBounds,
// then buildBounds). A file that loads must survive boundsToJson → parseBounds unchanged.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_contract.h"
#include "polar/bounds_file.h"

namespace {

bool sameSpec(const polar::BoundsSpec& a, const polar::BoundsSpec& b) {
    if (a.radii.size() != b.radii.size()) return false;
    for (std::size_t i = 0; i < a.radii.size(); ++i) {
        const polar::BoundSpec& x = a.radii[i];
        const polar::BoundSpec& y = b.radii[i];
        if (x.centre != y.centre || x.interpolate != y.interpolate || x.samples != y.samples) return false;
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = "sprites/fuzz.bounds.json";
    polar::SourceFile file{path, std::string(reinterpret_cast<const char*>(data), size)};
    polar::Result<polar::BoundsSpec> spec = polar::parseBounds(file);
    if (!spec) {
        polar::fuzz::checkError(spec.error(), file.text);
        return 0;
    }
    polar::Bounds bounds = polar::buildBounds(*spec);
    if (bounds.size() != spec->radii.size()) polar::fuzz::broken("buildBounds lost radii", "");

    polar::SourceFile saved{path, polar::boundsToJson(*spec)};
    polar::Result<polar::BoundsSpec> again = polar::parseBounds(saved);
    if (!again) polar::fuzz::broken("a saved bounds file does not load again", again.error().message());
    if (!sameSpec(*spec, *again)) polar::fuzz::broken("save → load changed the bounds", saved.text);
    return 0;
}
