// The one JSON object reader (scene/json_object_reader.h): each message of its wording table, in
// both wordings, so a swapped or lost difference fails here (the catalogue in
// bad_inputs_cli.cpp checks them again through the CLI).
#include <gtest/gtest.h>

#include <functional>

#include "error_text.h"
#include "marble/core/error.h"
#include "marble/scene/json_object_reader.h"

using namespace marble;
using marble::test::errorOf;
using json = nlohmann::json;

namespace {

// The message reading `key` of `obj` gives, as `read` reads it, in `wording`.
std::string message(const json& obj, JsonWording wording, const std::function<void(JsonObjectReader&)>& read) {
  return errorOf([&] {
    JsonObjectReader r(obj, "f.json", "p.", wording);
    read(r);
  });
}

const auto readNumber = [](JsonObjectReader& r) {
  float f = 0.0f;
  r.number("k", f, 0.0, 2.5);
};
const auto readInteger = [](JsonObjectReader& r) {
  long long i = 0;
  r.integer("k", i, 1, 8);
};
const auto readVec3 = [](JsonObjectReader& r) {
  glm::vec3 v(0.0f);
  r.vec3("k", v, 0.0, 1.0);
};

}  // namespace

TEST(JsonObjectReader, TheWordingsDifferExactlyAsTheTableSays) {
  const json text = {{"k", "x"}};
  EXPECT_EQ(message(text, JsonWording::Scene, readNumber), "f.json: p.k: expected a number, got string \"x\"");
  EXPECT_EQ(message(text, JsonWording::Material, readNumber), "f.json: p.k: expected a number in [0, 2.5], got string \"x\"");
  const json big = {{"k", 3}};
  for (JsonWording w : {JsonWording::Scene, JsonWording::Material})
    EXPECT_EQ(message(big, w, readNumber), "f.json: p.k: expected a number in [0, 2.5], got 3");

  const json twoPointZero = {{"k", 2.0}};
  EXPECT_EQ(message(twoPointZero, JsonWording::Scene, readInteger), "f.json: p.k: expected a whole number, got number 2.0");
  EXPECT_EQ(message(twoPointZero, JsonWording::Material, readInteger), "(no error)");
  EXPECT_EQ(message(text, JsonWording::Material, readInteger), "f.json: p.k: expected a whole number in [1, 8], got string \"x\"");
  const json nine = {{"k", 9}};
  for (JsonWording w : {JsonWording::Scene, JsonWording::Material})
    EXPECT_EQ(message(nine, w, readInteger), "f.json: p.k: expected a whole number in [1, 8], got 9");

  const json pair = {{"k", {0, 1}}};
  EXPECT_EQ(message(pair, JsonWording::Scene, readVec3), "f.json: p.k: expected an array of 3 numbers, got array [0,1]");
  EXPECT_EQ(message(pair, JsonWording::Material, readVec3),
            "f.json: p.k: expected an array of 3 numbers in [0, 1], got array [0,1]");
  const json outside = {{"k", {0, 1, 2}}};
  EXPECT_EQ(message(outside, JsonWording::Scene, readVec3), "f.json: p.k: component 2 must be in [0, 1], got 2");
  EXPECT_EQ(message(outside, JsonWording::Material, readVec3),
            "f.json: p.k: expected an array of 3 numbers in [0, 1], got [0,1,2]");
}

TEST(JsonObjectReader, UnknownKeysAreThoseNoReadAskedFor) {
  const json obj = {{"k", 1.0}, {"zz", 1}, {"aa", true}};
  for (JsonWording w : {JsonWording::Scene, JsonWording::Material}) {
    JsonObjectReader r(obj, "f.json", "p.", w);
    float f = 0.0f;
    EXPECT_TRUE(r.number("k", f, 0.0, 2.0));
    EXPECT_FALSE(r.number("absent", f, 0.0, 2.0));
    EXPECT_EQ(f, 1.0f);
    std::vector<std::string> warnings;
    r.warnUnknown(warnings);
    ASSERT_EQ(warnings.size(), 2u);
    if (w == JsonWording::Scene) {
      EXPECT_EQ(warnings[0], "f.json: p.aa: unknown key (ignored)");
    } else {
      EXPECT_EQ(warnings[0], "f.json: p.aa: unknown key 'aa' (ignored)");
    }
    EXPECT_NE(warnings[1].find("p.zz"), std::string::npos);
  }
}
