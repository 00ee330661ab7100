// The core JSON reader (harness/core/json_reader.hpp), the one every document model reads with:
// each typed access returns the value, and names the place and the problem when the value is
// missing or of the wrong kind.
#include <gtest/gtest.h>

#include <string>

#include "harness/core/json_reader.hpp"
#include "input_error.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;
using test::input_error;

const JsonReader kPointer("doc.json", JsonPathStyle::kPointer);
const JsonReader kDotted("preset.json", JsonPathStyle::kDottedKey);

bool says(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

TEST(JsonReader, NamesThePlaceInEitherStyle) {
  const ojson doc = ojson::parse(R"({"a": {"b": "x"}})");
  EXPECT_EQ(kPointer.child("/a", "b"), "/a/b");
  EXPECT_EQ(kPointer.element("/a", 2), "/a/2");
  EXPECT_EQ(kDotted.child("a", "b"), "a.b");
  EXPECT_EQ(kDotted.element("a", 2), "a[2]");
  EXPECT_EQ(input_error([&] { kPointer.string(doc["a"], "/a", "c"); }), "doc.json: /a/c: missing field");
  EXPECT_TRUE(says(input_error([&] { kDotted.number(nlohmann::ordered_json::parse(R"({"a": "x"})"), "", "a"); }),
                   "preset.json: key \"a\" has type string, expected a number"));
}

TEST(JsonReader, NonNegativeIntegersSignedOrUnsigned) {
  // A parsed 3 is unsigned; a 3 set from an int in memory is signed: both are a count.
  ojson doc = ojson::parse(R"({"parsed": 3, "negative": -1, "real": 1.5, "big": 4294967296})");
  doc["in_memory"] = static_cast<int>(3);
  ASSERT_FALSE(doc["in_memory"].is_number_unsigned());
  EXPECT_EQ(kPointer.uint64(doc, "", "parsed"), 3u);
  EXPECT_EQ(kPointer.uint64(doc, "", "in_memory"), 3u);
  EXPECT_EQ(kPointer.uint32(doc, "", "in_memory"), 3u);
  EXPECT_EQ(kPointer.uint64(doc, "", "big"), 4294967296u);
  EXPECT_TRUE(says(input_error([&] { kPointer.uint64(doc, "", "negative"); }),
                   "/negative: has type number, expected a non-negative integer"));
  EXPECT_TRUE(says(input_error([&] { kPointer.uint64(doc, "", "real"); }), "expected a non-negative integer"));
  EXPECT_TRUE(says(input_error([&] { kPointer.uint32(doc, "", "big"); }),
                   "/big: has type number, expected an unsigned 32-bit integer"));
  EXPECT_TRUE(says(input_error([&] { kPointer.uint32(doc, "", "negative"); }), "expected an unsigned 32-bit integer"));
}

TEST(JsonReader, TimesArePositive) {
  const ojson doc =
      ojson::parse(R"({"t": 0.5, "zero": 0, "negative": -2, "samples": [1, 2], "bad": [1, 0], "none": []})");
  EXPECT_EQ(kPointer.time(doc, "", "t"), 0.5);
  EXPECT_EQ(kPointer.times(doc, "", "samples"), (std::vector<double>{1, 2}));
  EXPECT_EQ(input_error([&] { kPointer.time(doc, "", "zero"); }), "doc.json: /zero: is not a positive time (0)");
  EXPECT_TRUE(says(input_error([&] { kPointer.time(doc, "", "negative"); }), "/negative: is not a positive time (-2)"));
  EXPECT_TRUE(says(input_error([&] { kPointer.times(doc, "", "bad"); }), "/bad/1: is not a positive time (0)"));
  EXPECT_TRUE(says(input_error([&] { kPointer.times(doc, "", "none"); }), "/none: is not a non-empty array"));
  EXPECT_TRUE(
      says(input_error([&] { kPointer.non_negative(doc["negative"], "/negative"); }), "/negative: is negative (-2)"));
  EXPECT_EQ(kPointer.non_negative(doc["zero"], "/zero"), 0.0);
}

TEST(JsonReader, OptionalMembersAbsentOrNullAreNone) {
  const ojson doc = ojson::parse(R"({"s": "x", "n": 2.5, "u": 7, "o": {"k": 1}, "null": null, "wrong": true})");
  EXPECT_EQ(kPointer.optional_string(doc, "", "s"), "x");
  EXPECT_EQ(kPointer.optional_number(doc, "", "n"), 2.5);
  EXPECT_EQ(kPointer.optional_uint64(doc, "", "u"), 7u);
  ASSERT_NE(kPointer.optional_object(doc, "", "o"), nullptr);
  EXPECT_EQ(kPointer.optional_object(doc, "", "o")->at("k"), 1);
  for (const char* key : {"absent", "null"}) {
    EXPECT_FALSE(kPointer.optional_string(doc, "", key)) << key;
    EXPECT_FALSE(kPointer.optional_number(doc, "", key)) << key;
    EXPECT_FALSE(kPointer.optional_uint64(doc, "", key)) << key;
    EXPECT_EQ(kPointer.optional_object(doc, "", key), nullptr) << key;
  }
  // Present but of another type is an error, never none.
  EXPECT_TRUE(says(input_error([&] { kPointer.optional_string(doc, "", "wrong"); }),
                   "/wrong: has type boolean, expected a string"));
  EXPECT_TRUE(says(input_error([&] { kPointer.optional_number(doc, "", "wrong"); }), "expected a number"));
  EXPECT_TRUE(
      says(input_error([&] { kPointer.optional_uint64(doc, "", "wrong"); }), "expected a non-negative integer"));
  EXPECT_TRUE(says(input_error([&] { kPointer.optional_object(doc, "", "wrong"); }), "expected an object"));
  EXPECT_TRUE(kPointer.flag(doc, "", "wrong", false));
  EXPECT_TRUE(kPointer.flag(doc, "", "absent", true));
  EXPECT_FALSE(kPointer.flag(doc, "", "absent", false));
  EXPECT_TRUE(
      says(input_error([&] { kPointer.flag(doc, "", "s", false); }), "/s: has type string, expected a boolean"));
}

TEST(JsonReader, ArraysAndMaps) {
  const ojson doc = ojson::parse(R"({"a": [1, 2.5], "e": [], "s": "x", "mixed": [1, "2"], "m": {"b": "1", "a": "2"},
                                     "bad_map": {"b": 1}})");
  EXPECT_EQ(kPointer.array(doc, "", "a").size(), 2u);
  EXPECT_EQ(kPointer.array(doc, "", "e").size(), 0u);
  EXPECT_EQ(kPointer.array(doc, "", "a", 2).size(), 2u);
  EXPECT_TRUE(says(input_error([&] { kPointer.array(doc, "", "a", 3); }),
                   "/a: has 2 elements, expected an array of 3 numbers"));
  EXPECT_TRUE(says(input_error([&] { kPointer.array(doc, "", "s"); }), "/s: has type string, expected an array"));
  EXPECT_EQ(kPointer.nonempty_array(doc, "", "a").size(), 2u);
  EXPECT_TRUE(says(input_error([&] { kPointer.nonempty_array(doc, "", "e"); }), "/e: is empty"));
  EXPECT_EQ(kPointer.numbers(doc, "", "a"), (std::vector<double>{1, 2.5}));
  EXPECT_TRUE(kPointer.numbers(doc, "", "e").empty());
  EXPECT_TRUE(
      says(input_error([&] { kPointer.numbers(doc, "", "mixed"); }), "/mixed/1: has type string, expected a number"));
  // In the document's order, not sorted.
  const auto map = kPointer.string_map(doc["m"], "/m");
  ASSERT_EQ(map.size(), 2u);
  EXPECT_EQ(map[0], (std::pair<std::string, std::string>{"b", "1"}));
  EXPECT_EQ(map[1], (std::pair<std::string, std::string>{"a", "2"}));
  EXPECT_TRUE(says(input_error([&] { kPointer.string_map(doc["bad_map"], "/bad_map"); }),
                   "/bad_map/b: has type number, expected a string"));
  EXPECT_TRUE(
      says(input_error([&] { kPointer.string_map(doc["a"], "/a"); }), "/a: has type array, expected an object"));
}

}  // namespace
}  // namespace vsgl
