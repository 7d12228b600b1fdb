// polarcade-collide: one detection pass over a scene, printed as JSON. It answers a modder's "why did
// these two collide?" and lets the engine be checked against an independent model.
#include <cstdio>
#include <string>

#include "cli.h"
#include "polar/json_writer.h"
#include "polar/scene_file.h"
#include "polar/world.h"

int main(int argc, char** argv) {
    polar::cli::Command app{
        "Runs one collision detection pass over a scene and prints the pairs as JSON; moves nothing.",
        "polarcade-collide"};
    std::string scenePath;
    bool all = false;
    std::string accuracyName;
    app.option("scene", scenePath, "Scene file (.json)").required();
    app.flag("--all", all, "List every tested pair, not only the hits");
    app.option(
           "--accuracy", accuracyName,
           "Narrow-phase level, overriding the scene's \"accuracy\": bounds (each bounds file's interpolate "
           "flag), circle, nearest, chord, all-radii or exact")
        .check([](const std::string& name) {
            return polar::accuracyFromName(name) ? std::string()
                                                 : "unknown accuracy level \"" + name +
                                                       "\"; expected one of " + polar::accuracyNameList();
        });
    if (int code = app.parse(argc, argv); code >= 0) return code;

    polar::Result<polar::SceneDef> scene = polar::loadScene(scenePath, polar::diskReader());
    if (!scene) {
        std::fprintf(stderr, "%s\n", scene.error().message().c_str());
        return polar::cli::kBadInput;
    }
    if (!accuracyName.empty()) scene->world.accuracy = *polar::accuracyFromName(accuracyName);
    polar::World world = polar::buildWorld(*scene);
    // One pair per line, keys in the documented order; numbers round-trip exactly.
    std::vector<polar::PairReport> reports = world.detect(all);
    std::printf("{\"pairs\": [");
    for (std::size_t i = 0; i < reports.size(); ++i) {
        const polar::PairTest& t = reports[i].test;
        polar::JsonWriter pair;
        pair.beginObject()
            .member("a", world.objects()[reports[i].a].name)
            .member("b", world.objects()[reports[i].b].name)
            .member("hit", t.hit)
            .member("kind", polar::contactKindName(t.kind))
            .member("distance", t.distance)
            .member("ra", t.ra)
            .member("rb", t.rb)
            .endObject();
        std::printf("%s\n  %s", i ? "," : "", pair.text().c_str());
    }
    std::printf("%s]}\n", reports.empty() ? "" : "\n");
    return 0;
}
