#pragma once
#include <string>
#include <vector>

#include "polar/atomic_file.h"
#include "polar/bound.h"
#include "polar/error.h"

namespace polar {

// One Bound exactly as a bounds file writes it: the modder's sample order and values are
// kept, so load → save → load changes nothing.
struct BoundSpec {
    Vec2 centre = Vec2::Zero();
    bool interpolate = false;
    std::vector<DegreeSample> samples;  // [degrees, radius] in file order
};
// The older name for a BoundSpec, kept so programs written against it still compile.
using RadiiSpec = BoundSpec;

// The contents of a `.bounds.json` file:
//   {"format": 1, "radii": [{"centre": [0, 0], "interpolate": true,
//                            "samples": [[0, 30], [90, 24.5], [180, 31], [270, 22]]}]}
// `centre` defaults to [0, 0] and `interpolate` to false. Unknown keys are errors.
struct BoundsSpec {
    std::vector<BoundSpec> radii;  // named after the file's "radii" key, which modders' files keep
};

inline constexpr int kBoundsFormat = 1;

// Parses and validates a bounds file.
Result<BoundsSpec> parseBounds(const SourceFile& file);
// The runtime bounds of a validated spec, in file order.
Bounds buildBounds(const BoundsSpec& spec);
// Reads, parses and builds a bounds file through `reader`.
Result<BoundsPtr> loadBounds(const std::string& path, const FileReader& reader);
// The spec as JSON text, samples in the modder's order, every number exactly as loaded.
std::string boundsToJson(const BoundsSpec& spec);
// Writes boundsToJson(spec) to `path` atomically (temporary file, then rename); comments of an old
// file are not kept. `fault` is a test hook (atomic_file.h).
std::optional<Error> saveBounds(const std::string& path, const BoundsSpec& spec,
                                const AtomicWriteFault& fault = {});

}  // namespace polar
