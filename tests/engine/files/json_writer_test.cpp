#include "polar/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "polar/json_doc.h"

namespace polar {
namespace {

TEST(JsonWriter, LaysOutOneValueALineInTheOrderWritten) {
    JsonWriter w(2);
    w.beginObject().member("format", 2).member("name", "zed");
    w.key("tags").beginArray().value("b").value("a").endArray();
    w.key("empty").beginArray().endArray();
    w.key("none").beginObject().endObject();
    w.key("inner").beginObject().member("y", true).member("x", false).key("n").null().endObject();
    w.endObject();
    EXPECT_EQ(w.text(),
              "{\n"
              "  \"format\": 2,\n"
              "  \"name\": \"zed\",\n"
              "  \"tags\": [\n"
              "    \"b\",\n"
              "    \"a\"\n"
              "  ],\n"
              "  \"empty\": [],\n"
              "  \"none\": {},\n"
              "  \"inner\": {\n"
              "    \"y\": true,\n"
              "    \"x\": false,\n"
              "    \"n\": null\n"
              "  }\n"
              "}");
}

TEST(JsonWriter, ANegativeIndentIsOneCompactLine) {
    JsonWriter w;
    w.beginObject().member("a", "x").member("hit", true).key("v").beginArray().value(1).value(2.5).endArray();
    w.endObject();
    EXPECT_EQ(w.text(), R"({"a":"x","hit":true,"v":[1,2.5]})");
    JsonWriter scalar;
    scalar.value(7u);
    EXPECT_EQ(scalar.text(), "7");
}

TEST(JsonWriter, NumbersReadBackExactly) {
    EXPECT_EQ(jsonNumberText(0.1), "0.1");
    EXPECT_EQ(jsonNumberText(2.0), "2.0");
    EXPECT_EQ(jsonNumberText(-0.0), "-0.0");
    EXPECT_EQ(jsonNumberText(1e100), "1e+100");
    EXPECT_EQ(jsonNumberText(1.0 / 3.0), "0.3333333333333333");
    JsonWriter w;
    w.beginArray().value(-3).value(std::numeric_limits<std::uint64_t>::max()).value(1.0 / 3.0);
    w.value(std::nan("")).value(std::numeric_limits<double>::infinity()).endArray();
    EXPECT_EQ(w.text(), "[-3,18446744073709551615,0.3333333333333333,null,null]");
    // Read back by JsonDoc: the same double, bit for bit.
    for (double v : {0.1, 1.0 / 3.0, 6.02214076e23, -1.5e-300, 123456.789}) {
        Result<JsonDoc> doc = JsonDoc::parse(SourceFile{"n.json", jsonNumberText(v)});
        ASSERT_TRUE(doc.ok()) << jsonNumberText(v);
        EXPECT_EQ(doc->root().number(""), v) << jsonNumberText(v);
    }
}

TEST(JsonWriter, StringsAreEscaped) {
    JsonWriter w;
    w.beginArray()
        .value("q\"b\\n\nt\t\x01")
        .value("\u00e9\u20ac")
        .value(std::string("\xff"
                           "a"))
        .endArray();
    EXPECT_EQ(w.text(),
              "[\"q\\\"b\\\\n\\nt\\t\\u0001\",\"\u00e9\u20ac\",\"\xEF\xBF\xBD"
              "a\"]");
}

// What the writer writes, JsonDoc reads back: the same values, members in the same order.
TEST(JsonWriter, JsonDocReadsBackWhatItWrote) {
    JsonWriter w(2);
    w.beginObject().member("zeta", 1).member("alpha", "a\nb").key("list").beginArray();
    for (int k = 0; k < 3; ++k) w.beginObject().member("k", k).endObject();
    w.endArray().endObject();
    Result<JsonDoc> doc = JsonDoc::parse(SourceFile{"w.json", w.text()});
    ASSERT_TRUE(doc.ok()) << doc.error().message();
    JsonNode root = doc->root();
    ASSERT_EQ(root.size(), 3u);
    EXPECT_EQ(root.at(0).key(), "zeta");
    EXPECT_EQ(root.at(1).string(""), "a\nb");
    std::vector<JsonNode> list = root.require("list", "").items("");
    ASSERT_EQ(list.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(list[k].require("k", "").integer(""), k);
}

}  // namespace
}  // namespace polar
