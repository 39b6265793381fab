// Scene validation against parameter schemas: every fault with its JSON pointer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "kernel/scene/json_file.hpp"
#include "kernel/scene/validate.hpp"
#include "kernel/text/did_you_mean.hpp"

using moreau::InputError;
using moreau::Schema;
using moreau::kernel::Validation;
using moreau::kernel::validate_object;
using nlohmann::json;

namespace {

Schema disk_like() {
  Schema s;
  s.number("radius", "disk radius").units("m").gt(0);
  s.number("friction", "friction coefficient").min(0).fallback(0.3);
  s.integer("every", "frequency").min(1).fallback(1);
  s.vector("position", "where", moreau::length::dimension);
  s.vector("velocity", "imposed", moreau::length::dimension).allow_null_items().optional();
  s.string("mode", "mode").one_of({"warn", "stop"}).fallback("warn");
  s.boolean("fixed", "fixed").fallback(false);
  return s;
}

std::vector<std::string> errors_for(const json& j, int dim = 2) {
  std::vector<InputError> errors;
  Validation v{dim, errors};
  validate_object(j, disk_like(), "/bodies/3", v);
  std::vector<std::string> out;
  for (const auto& e : errors) out.push_back(e.describe());
  return out;
}

}  // namespace

TEST(Validate, ValidObjectGetsDefaults) {
  std::vector<InputError> errors;
  Validation v{2, errors};
  json out = validate_object(json{{"radius", 0.1}, {"position", {0, 1}}}, disk_like(), "/b", v);
  EXPECT_TRUE(errors.empty());
  EXPECT_EQ(out["friction"], 0.3);
  EXPECT_EQ(out["mode"], "warn");
  EXPECT_EQ(out["fixed"], false);
  EXPECT_FALSE(out.contains("velocity"));
}

TEST(Validate, UnknownKeySuggestsNearest) {
  auto e = errors_for(json{{"radius", 0.1}, {"position", {0, 1}}, {"raduis", 2}});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "at /bodies/3/raduis: unknown key \"raduis\"; did you mean \"radius\"?");
}

TEST(Validate, UnknownKeyFarFromAnyListsValidKeys) {
  auto e = errors_for(json{{"radius", 0.1}, {"position", {0, 1}}, {"zzzzzzzzzz", 2}});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NE(e[0].find("valid keys: radius, friction, every, position, velocity, mode, fixed"), std::string::npos) << e[0];
}

TEST(Validate, ReportsEveryErrorAtOnce) {
  auto e = errors_for(json{{"radius", -1}, {"every", 1.5}, {"position", {0, 1, 2}}, {"mode", "loud"}, {"fixed", 1}});
  ASSERT_EQ(e.size(), 5u);
  EXPECT_EQ(e[0], "at /bodies/3/radius: value -1 out of range: expected > 0");
  EXPECT_EQ(e[1], "at /bodies/3/every: expected an integer, got a number");
  EXPECT_EQ(e[2], "at /bodies/3/position: expected 2 numbers (dimension 2), got 3");
  EXPECT_EQ(e[3], "at /bodies/3/mode: unexpected value \"loud\": expected one of \"warn\", \"stop\"");
  EXPECT_EQ(e[4], "at /bodies/3/fixed: expected a boolean (true or false), got an integer");
}

TEST(Validate, MissingRequiredKey) {
  auto e = errors_for(json{{"position", {0, 1}}});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "at /bodies/3/radius: missing required key \"radius\" (disk radius)");
}

TEST(Validate, VectorItemsCheckedWithTheirIndex) {
  auto e = errors_for(json{{"radius", 1}, {"position", {0, "a", 1}}, {"velocity", {nullptr, 1, 0}}}, 3);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "at /bodies/3/position/1: expected a number, got a string");
  e = errors_for(json{{"radius", 1}, {"position", {0, nullptr}}});
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "at /bodies/3/position/1: expected a number, got null");
}

TEST(Validate, NotAnObject) {
  auto e = errors_for(json::array());
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0], "at /bodies/3: expected an object, got an array");
}

TEST(Validate, NearestNameIgnoresCaseAndPointerTokens) {
  using moreau::kernel::did_you_mean;
  using moreau::kernel::nearest_name;
  EXPECT_EQ(nearest_name("gravty", {"gravity", "bodies"}), "gravity");
  EXPECT_EQ(nearest_name("xyz", {"gravity", "bodies"}), "");
  EXPECT_EQ(nearest_name("Gravity", {"gravity", "bodies"}), "gravity");
  EXPECT_EQ(nearest_name("NLGS", {"apgd", "nlgs", "psor"}), "nlgs");
  EXPECT_EQ(nearest_name("Sphre", {"sphere", "plane"}), "sphere");
  EXPECT_EQ(did_you_mean("Disk", {"disk", "segment"}, '\''), "; did you mean 'disk'?");
  EXPECT_EQ(did_you_mean("disk", {"disk"}), "") << "no suggestion of the name itself";
  EXPECT_EQ(did_you_mean("zzzzzz", {"disk"}), "");
  EXPECT_EQ(moreau::kernel::pointer_token("a/b~c"), "a~1b~0c");
}

TEST(JsonFile, MalformedJsonGivesLineAndColumn) {
  const auto path = std::filesystem::temp_directory_path() / "moreau_test_bad.json";
  std::ofstream(path) << "{\n  \"format\": \"moreau-scene/1\",\n  \"dimension\": 2,,\n}\n";
  try {
    moreau::kernel::read_json_file(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(std::string(e.what()).find("malformed JSON at line 3, column 18"), std::string::npos) << e.what();
  }
}

TEST(JsonFile, MissingFile) {
  try {
    moreau::kernel::read_json_file("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.describe(), "/nonexistent/scene.json: cannot open the file for reading");
  }
}
