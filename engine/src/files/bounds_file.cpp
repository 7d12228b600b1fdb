#include "polar/bounds_file.h"

#include "files/bounds_reader.h"
#include "polar/json_writer.h"

namespace polar {
namespace {

BoundSpec readBoundSpec(const JsonNode& node) {
    node.allowKeys({"centre", "interpolate", "samples"});
    BoundSpec spec;
    if (auto centre = node.find("centre")) spec.centre = centre->vec2("a centre [x, y] in sprite pixels");
    if (auto interpolate = node.find("interpolate")) spec.interpolate = interpolate->boolean("true or false");
    JsonNode samples = node.require("samples", "\"samples\": [[angle, radius], ...]");
    for (const JsonNode& sample : samples.items("an array of [angle in degrees, radius] pairs")) {
        if (!sample.isArray() || sample.size() != 2)
            sample.fail("found " + sample.kindName() +
                            (sample.isArray() ? " of " + std::to_string(sample.size()) + " items" : ""),
                        "a sample [angle in degrees, radius]");
        spec.samples.push_back(
            {sample.at(0).number("an angle in degrees"), sample.at(1).number("a radius in sprite pixels")});
    }
    if (auto problem = Bound::check(spec.samples, spec.interpolate)) {
        if (problem->index == SampleProblem::kWholeList) samples.fail(problem->what, problem->expected);
        samples.at(problem->index).fail(problem->what, problem->expected);
    }
    return spec;
}

}  // namespace

BoundsSpec readBounds(const JsonNode& node, bool formatRequired) {
    node.allowKeys({"format", "radii"});
    if (auto format = node.find("format")) {
        int version = format->integer("the format number 1");
        if (version != kBoundsFormat)
            format->fail("unsupported format " + std::to_string(version), "\"format\": 1");
    } else if (formatRequired) {
        node.fail("missing key \"format\"", "\"format\": 1 at the top of a bounds file");
    }
    BoundsSpec spec;
    JsonNode radii = node.require("radii", "\"radii\": [ {\"samples\": ...}, ... ]");
    for (const JsonNode& r : radii.items("an array of radii objects")) spec.radii.push_back(readBoundSpec(r));
    return spec;
}

Result<BoundsSpec> parseBounds(const SourceFile& file) {
    Result<JsonDoc> doc = JsonDoc::parse(file);
    if (!doc) return doc.error();
    return catchLoadFailure<BoundsSpec>([&] { return readBounds(JsonNode::root(*doc), true); });
}

Bounds buildBounds(const BoundsSpec& spec) {
    Bounds bounds;
    bounds.reserve(spec.radii.size());
    for (const BoundSpec& r : spec.radii)
        bounds.push_back(Bound::fromDegrees(r.centre, r.samples, r.interpolate));
    return bounds;
}

Result<BoundsPtr> loadBounds(const std::string& path, const FileReader& reader) {
    std::optional<SourceFile> file = reader(path);
    if (!file)
        return Error{path, 0, 0, "cannot read the bounds file", "an existing, readable .bounds.json file"};
    Result<BoundsSpec> spec = parseBounds(*file);
    if (!spec) return spec.error();
    return std::make_shared<const Bounds>(buildBounds(*spec));
}

std::string boundsToJson(const BoundsSpec& spec) {
    std::string out = "{\n  \"format\": " + std::to_string(kBoundsFormat) + ",\n  \"radii\": [";
    for (std::size_t i = 0; i < spec.radii.size(); ++i) {
        const BoundSpec& r = spec.radii[i];
        out += i ? ",\n    {\n" : "\n    {\n";
        out += "      \"centre\": [" + jsonNumberText(r.centre.x()) + ", " + jsonNumberText(r.centre.y()) +
               "],\n";
        out += std::string("      \"interpolate\": ") + (r.interpolate ? "true" : "false") + ",\n";
        out += "      \"samples\": [";
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            out += k ? ",\n        " : "\n        ";
            out += "[" + jsonNumberText(r.samples[k][0]) + ", " + jsonNumberText(r.samples[k][1]) + "]";
        }
        out += "\n      ]\n    }";
    }
    out += spec.radii.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return out;
}

std::optional<Error> saveBounds(const std::string& path, const BoundsSpec& spec,
                                const AtomicWriteFault& fault) {
    return writeFileAtomically(path, boundsToJson(spec), fault);
}

}  // namespace polar
