#pragma once
#include "polar/bounds_file.h"
#include "polar/json_doc.h"

namespace polar {

// Reads a bounds object inside any document: a whole bounds file, or a scene's inline "bounds"
// (`formatRequired` false: "format" may be left out there). Throws LoadFailure.
BoundsSpec readBounds(const JsonNode& node, bool formatRequired);

}  // namespace polar
