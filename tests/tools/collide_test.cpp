// Runs the polarcade-collide executable and checks its output, exit codes and numbers. The numbers
// are checked against a model written here from the plain formulas of the rule (libm trigonometry,
// an explicit matrix inverse, line intersection for straight edges); it calls nothing in the engine.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>
#include "run_command.h"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

using Outcome = polar::testing::CommandOutcome;

Outcome collide(const std::vector<std::string>& args) {
    return polar::testing::run(POLARCADE_COLLIDE, args);
}

std::string data(const std::string& name) {
    return std::string(POLAR_TEST_DATA) + "/" + name;
}

// ---- The independent model -------------------------------------------------------------------

struct Vec {
    double x = 0, y = 0;
};
Vec operator+(Vec a, Vec b) {
    return {a.x + b.x, a.y + b.y};
}
Vec operator-(Vec a, Vec b) {
    return {a.x - b.x, a.y - b.y};
}
Vec operator*(double s, Vec a) {
    return {s * a.x, s * a.y};
}
double norm(Vec a) {
    return std::sqrt(a.x * a.x + a.y * a.y);
}

constexpr double kPi = 3.14159265358979323846;
double reduce360(double d) {
    return std::fmod(std::fmod(d, 360.0) + 360.0, 360.0);
}

struct Radii {
    Vec centre;
    bool interpolate = false;
    std::vector<std::pair<double, double>> samples;  // (degrees in [0, 360), radius), ascending

    // Nearest by circular distance, ties to the smaller angle; or the straight edge between the
    // neighbours, where the ray meets the segment joining their points.
    double radius(double degrees) const {
        double a = reduce360(degrees);
        if (!interpolate) {
            double best = INFINITY, r = 0;
            for (auto [angle, radius] : samples) {
                double d = std::fabs(a - angle);
                d = std::min(d, 360 - d);
                if (d < best - 1e-9) best = d, r = radius;
            }
            return r;
        }
        std::size_t k = samples.size() - 1;
        for (std::size_t i = 0; i < samples.size(); ++i)
            if (samples[i].first <= a) k = i;
        auto point = [](std::pair<double, double> s) {
            return Vec{s.second * std::cos(s.first * kPi / 180), s.second * std::sin(s.first * kPi / 180)};
        };
        Vec p1 = point(samples[k]), p2 = point(samples[(k + 1) % samples.size()]), e = p2 - p1;
        Vec d{std::cos(a * kPi / 180), std::sin(a * kPi / 180)};
        return (p1.x * e.y - p1.y * e.x) / (d.x * e.y - d.y * e.x);
    }
};

struct Object {
    std::string name;
    Vec position;
    double l[2][2] = {{1, 0}, {0, 1}};  // L = R(θ)·diag(sx, sy)
    std::vector<Radii> radii;
    bool collisions = false, container = false, ignoreContainers = false;

    Vec apply(Vec q) const { return {l[0][0] * q.x + l[0][1] * q.y, l[1][0] * q.x + l[1][1] * q.y}; }
    Vec worldCentre(std::size_t k) const { return position + apply(radii[k].centre); }

    // The world radius toward w: map the unit direction back through L⁻¹ to q; the outline point
    // radius(angle q)·q/|q| maps forward to (radius/|q|)·ŵ, so the world radius is radius/|q|.
    double worldRadius(std::size_t k, Vec w) const {
        double det = l[0][0] * l[1][1] - l[0][1] * l[1][0];
        if (det == 0) return 0;
        Vec unit = (1 / norm(w)) * w;
        Vec q{(l[1][1] * unit.x - l[0][1] * unit.y) / det, (-l[1][0] * unit.x + l[0][0] * unit.y) / det};
        return radii[k].radius(std::atan2(q.y, q.x) * 180 / kPi) / norm(q);
    }

    std::size_t closestRadiiTo(Vec target) const {
        std::size_t best = 0;
        double bestDistance = INFINITY;
        for (std::size_t k = 0; k < radii.size(); ++k) {
            Vec d = worldCentre(k) - target;
            double dist = d.x * d.x + d.y * d.y;
            if (dist < bestDistance) bestDistance = dist, best = k;
        }
        return best;
    }
};

Radii readRadii(const json& j) {
    Radii r;
    if (j.contains("centre")) r.centre = {j["centre"][0].get<double>(), j["centre"][1].get<double>()};
    r.interpolate = j.value("interpolate", false);
    for (const json& s : j["samples"])
        r.samples.push_back({reduce360(s[0].get<double>()), s[1].get<double>()});
    std::sort(r.samples.begin(), r.samples.end());
    return r;
}

struct Scene {
    std::vector<Object> objects;
    bool containers = false;
};

Scene readScene(const std::string& path) {
    json doc = json::parse(polar::testing::readFile(path), nullptr, true, true);
    Scene scene;
    for (const json& e : doc.value("effects", json::array())) scene.containers |= e == "containers";
    for (const json& o : doc["objects"]) {
        Object obj;
        obj.name = o["name"];
        if (o.contains("position"))
            obj.position = {o["position"][0].get<double>(), o["position"][1].get<double>()};
        double theta = reduce360(o.value("rotation", 0.0)) * kPi / 180;
        double sx = 1, sy = 1;
        if (o.contains("scale")) {
            if (o["scale"].is_number())
                sx = sy = o["scale"].get<double>();
            else
                sx = o["scale"][0].get<double>(), sy = o["scale"][1].get<double>();
        }
        obj.l[0][0] = std::cos(theta) * sx, obj.l[0][1] = -std::sin(theta) * sy;
        obj.l[1][0] = std::sin(theta) * sx, obj.l[1][1] = std::cos(theta) * sy;
        if (o.contains("bounds")) {
            json bounds = o["bounds"].is_object()
                              ? o["bounds"]
                              : json::parse(polar::testing::readFile(fs::path(path).parent_path() /
                                                                     o["bounds"].get<std::string>()),
                                            nullptr, true, true);
            for (const json& r : bounds["radii"]) obj.radii.push_back(readRadii(r));
        }
        for (const json& f : o.value("flags", json::array())) {
            obj.collisions |= f == "collisions";
            obj.container |= f == "container";
            obj.ignoreContainers |= f == "ignore_containers";
        }
        scene.objects.push_back(obj);
    }
    return scene;
}

struct ModelPair {
    std::string a, b;
    bool hit = false;
    std::string kind;
    double distance = 0, ra = 0, rb = 0;
    double margin = 0;  // how far from the rule's threshold, relative
};

std::vector<ModelPair> model(const Scene& scene) {
    std::vector<ModelPair> pairs;
    const auto& objs = scene.objects;
    for (std::size_t i = 0; i < objs.size(); ++i) {
        for (std::size_t j = i + 1; j < objs.size(); ++j) {
            const Object &A = objs[i], &B = objs[j];
            if (!A.collisions || !B.collisions || A.radii.empty() || B.radii.empty()) continue;
            if (A.container && B.container) continue;
            if ((A.container || B.container) &&
                (!scene.containers || (A.container ? B.ignoreContainers : A.ignoreContainers)))
                continue;
            std::size_t acr = A.closestRadiiTo(B.position);
            std::size_t bcr = B.closestRadiiTo(A.worldCentre(acr));
            Vec u = B.worldCentre(bcr) - A.worldCentre(acr);
            double D = u.x * u.x + u.y * u.y;
            if (D == 0) u = {1, 0};
            ModelPair p;
            p.a = A.name;
            p.b = B.name;
            p.distance = std::sqrt(D);
            if (!A.container && !B.container) {
                p.kind = "contact";
                p.ra = A.worldRadius(acr, u);
                p.rb = B.worldRadius(bcr, -1 * u);
                double sum = (p.ra + p.rb) * (p.ra + p.rb);
                p.hit = D <= sum;
                p.margin = std::fabs(sum - D) / sum;
            } else {
                p.kind = "container";
                Vec out = A.container ? u : -1 * u;  // from the container toward the object it holds
                double wall = A.container ? A.worldRadius(acr, out) : B.worldRadius(bcr, out);
                double side = A.container ? B.worldRadius(bcr, out) : A.worldRadius(acr, out);
                p.ra = A.container ? wall : side;
                p.rb = A.container ? side : wall;
                p.hit = p.distance + side >= wall;
                p.margin = std::fabs(p.distance + side - wall) / wall;
            }
            pairs.push_back(p);
        }
    }
    return pairs;
}

// ---- The tests -------------------------------------------------------------------------------

const std::vector<std::string> kKeys = {"a", "b", "hit", "kind", "distance", "ra", "rb"};

// Parses the tool's output, checking its shape: {"pairs": [{"a", "b", "hit", "kind", "distance", "ra",
// "rb"}]}.
nlohmann::ordered_json parseOutput(const std::string& out) {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(out);
    EXPECT_TRUE(doc.is_object());
    EXPECT_EQ(doc.size(), 1u);
    EXPECT_TRUE(doc["pairs"].is_array());
    for (const auto& pair : doc["pairs"]) {
        std::vector<std::string> keys;
        for (auto it = pair.begin(); it != pair.end(); ++it) keys.push_back(it.key());
        EXPECT_EQ(keys, kKeys);
        EXPECT_TRUE(pair["a"].is_string());
        EXPECT_TRUE(pair["b"].is_string());
        EXPECT_TRUE(pair["hit"].is_boolean());
        EXPECT_TRUE(pair["kind"] == "contact" || pair["kind"] == "container") << pair.dump();
        for (const char* k : {"distance", "ra", "rb"}) EXPECT_TRUE(pair[k].is_number()) << k;
    }
    return doc;
}

void expectMatchesModel(const nlohmann::ordered_json& pairs, const std::vector<ModelPair>& expected) {
    ASSERT_EQ(pairs.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const auto& got = pairs[i];
        const ModelPair& want = expected[i];
        std::string label = want.a + " / " + want.b;
        EXPECT_EQ(got["a"], want.a) << i;
        EXPECT_EQ(got["b"], want.b) << i;
        EXPECT_EQ(got["kind"], want.kind) << label;
        EXPECT_EQ(got["hit"], want.hit) << label;
        EXPECT_NEAR(got["distance"].get<double>(), want.distance, 1e-9 * (1 + want.distance)) << label;
        EXPECT_NEAR(got["ra"].get<double>(), want.ra, 1e-9 * (1 + want.ra)) << label;
        EXPECT_NEAR(got["rb"].get<double>(), want.rb, 1e-9 * (1 + want.rb)) << label;
    }
}

TEST(Collide, HelpExitsZero) {
    Outcome r = collide({"--help"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("--all"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("polarcade-collide"), std::string::npos) << r.out;
}

TEST(Collide, ListsHitsOnlyByDefaultAndEveryTestedPairWithAll) {
    Scene scene = readScene(data("collide/mixed.json"));
    std::vector<ModelPair> all = model(scene), hits;
    for (const ModelPair& p : all) {
        ASSERT_GT(p.margin, 1e-6) << p.a << " / " << p.b << " is too close to its threshold to compare";
        if (p.hit) hits.push_back(p);
    }
    // The scene exercises what it should: both kinds, hits and misses, the container as A and as B,
    // coincident centres.
    ASSERT_GE(hits.size(), 8u);
    ASSERT_GT(all.size(), 2 * hits.size());
    auto has = [&](const std::string& a, const std::string& b, bool hit) {
        for (const ModelPair& p : all)
            if (p.a == a && p.b == b && p.hit == hit) return true;
        return false;
    };
    EXPECT_TRUE(has("arena", "ship", true));   // container as A
    EXPECT_TRUE(has("rock-1", "cage", true));  // container as B
    EXPECT_TRUE(has("star", "cage", false));   // inside the cage
    EXPECT_TRUE(has("star", "twin", true));    // coincident centres
    EXPECT_TRUE(has("mirror", "bell", true));  // a mirror and several radii
    EXPECT_TRUE(has("offset", "bell", true));  // Bcr is the radii nearest Acr's centre, not A's position

    Outcome r = collide({data("collide/mixed.json")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    expectMatchesModel(parseOutput(r.out)["pairs"], hits);

    Outcome a = collide({"--all", data("collide/mixed.json")});
    ASSERT_EQ(a.exitCode, 0) << a.err;
    expectMatchesModel(parseOutput(a.out)["pairs"], all);
    // Pairs the rules leave out never appear: two containers, a container with ignore_containers,
    // objects without the collisions flag or without bounds.
    for (const char* name : {"quiet", "empty"})
        EXPECT_EQ(a.out.find(std::string("\"") + name + "\""), std::string::npos);
    EXPECT_EQ(a.out.find("{\"a\":\"arena\",\"b\":\"cage\""), std::string::npos);
    EXPECT_EQ(a.out.find("{\"a\":\"arena\",\"b\":\"passer\""), std::string::npos);
    EXPECT_NE(a.out.find("{\"a\":\"rock-1\",\"b\":\"passer\""), std::string::npos);
}

TEST(Collide, AnswersTheExampleScene) {
    std::vector<ModelPair> expected;
    for (const ModelPair& p : model(readScene(data("example.json"))))
        if (p.hit) expected.push_back(p);
    ASSERT_EQ(expected.size(), 1u);
    Outcome r = collide({data("example.json")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto doc = parseOutput(r.out);
    expectMatchesModel(doc["pairs"], expected);
    EXPECT_EQ(doc["pairs"][0]["a"], "rock-1");  // scene order
    EXPECT_EQ(doc["pairs"][0]["b"], "ship");
}

TEST(Collide, NoHitsIsAnEmptyList) {
    fs::path dir = fs::path(testing::TempDir()) / ("polar-collide-empty-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "s.json") << R"({"format": 1, "effects": ["collisions"], "objects": [
        {"name": "a", "bounds": {"radii": [{"samples": [[0, 1]]}]}, "flags": ["collisions"]},
        {"name": "b", "bounds": {"radii": [{"samples": [[0, 1]]}]}, "position": [5, 0], "flags": ["collisions"]}]})";
    Outcome r = collide({(dir / "s.json").string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(parseOutput(r.out)["pairs"].empty()) << r.out;
    Outcome a = collide({"--all", (dir / "s.json").string()});
    auto pairs = parseOutput(a.out)["pairs"];
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0]["hit"], false);
    EXPECT_EQ(pairs[0]["distance"], 5.0);
    fs::remove_all(dir);
}

TEST(Collide, BadInputExitsTwoWithTheErrorOnStderr) {
    fs::path dir = fs::path(testing::TempDir()) / ("polar-collide-bad-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "syntax.json") << "{\"format\": 1,\n  \"objects\": [}\n";
    std::ofstream(dir / "flag.json") << "{\"format\": 1, \"effects\": [\"collisions\"],\n \"objects\": "
                                        "[{\"name\": \"a\", \"flags\": [\"collision\"]}]}";
    std::ofstream(dir / "bounds.json")
        << "{\"format\": 1, \"objects\": [{\"name\": \"a\",\n   \"bounds\": \"nowhere.bounds.json\"}]}";
    struct Case {
        std::vector<std::string> args;
        std::string stderrStart;
    };
    std::string d = dir.string();
    for (const Case& c :
         {Case{{d + "/syntax.json"}, d + "/syntax.json:2:15: "},
          Case{{d + "/flag.json"}, d + "/flag.json:2:38: unknown flag \"collision\"; expected one of"},
          Case{{"--all", d + "/bounds.json"}, d + "/bounds.json:2:14: cannot read bounds file"},
          Case{{d + "/missing.json"}, d + "/missing.json: cannot read the scene file"},
          Case{{}, "polarcade-collide: "}, Case{{"--bogus", d + "/syntax.json"}, "polarcade-collide: "},
          Case{{d + "/syntax.json", d + "/flag.json"}, "polarcade-collide: "}}) {
        Outcome r = collide(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.stderrStart;
        EXPECT_EQ(r.err.rfind(c.stderrStart, 0), 0u) << "stderr: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
        EXPECT_TRUE(r.out.empty()) << "nothing half-written on stdout: " << r.out;
    }
    fs::remove_all(dir);
}

}  // namespace
