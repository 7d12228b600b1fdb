// tools/server/openapi.json names every route the server registers, and nothing else.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "routes.h"

namespace polar::server {
namespace {

TEST(OpenApi, NamesEveryRouteTheServerRegistersAndNoOther) {
    std::ifstream in(POLAR_OPENAPI_FILE);
    ASSERT_TRUE(in) << POLAR_OPENAPI_FILE;
    nlohmann::json doc = nlohmann::json::parse(in);
    std::set<std::string> documented, registered;
    for (const auto& [path, methods] : doc.at("paths").items())
        for (const auto& [method, operation] : methods.items()) {
            std::string upper = method;
            for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            documented.insert(upper + " " + path);
            EXPECT_TRUE(operation.contains("responses")) << upper << " " << path;
        }
    for (const RouteName& route : routeNames())
        registered.insert(std::string(route.method) + " " + route.path);
    for (const std::string& route : registered)
        EXPECT_TRUE(documented.count(route)) << route << " is not in openapi.json";
    for (const std::string& route : documented)
        EXPECT_TRUE(registered.count(route))
            << route << " is in openapi.json but the server has no such route";
    EXPECT_GE(registered.size(), 8u);
}

}  // namespace
}  // namespace polar::server
