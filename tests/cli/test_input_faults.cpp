// Scene input that once escaped validation (issue 11: mutated copies of configs/ under
// `moreau check`): every one is exit 2 with the file and the JSON pointer, never
// "internal error", a silently accepted value or a signal. The same inputs are in
// tests/fuzz/regressions/scene/, replayed through the fuzz target.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "bad_input.hpp"
#include "cli_runner.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

TEST(InputFaults, ADuplicatedKeyIsAnErrorNamingTheKeyAndItsPointer) {
  // JSON allows it and the parser kept the last value: a silent overwrite.
  expect_bad_input("dup_key", replace(projectile_scene(), "\"mass\": 2.0,", "\"mass\": 2.0, \"mass\": 20.0,"),
                   "at /bodies/0/mass: duplicate key \"mass\"");
  expect_bad_input("dup_top", replace(projectile_scene(), "\"dimension\": 2,", "\"dimension\": 2, \"dimension\": 3,"),
                   "at /dimension: duplicate key \"dimension\"");
}

TEST(InputFaults, ANumberTooLargeForADoubleIsAnErrorAtItsPointer) {
  expect_bad_input("big", replace(projectile_scene(), "\"mass\": 2.0", "\"mass\": 1e400"),
                   "at /bodies/0/mass: number out of range");
  expect_bad_input("big_item", replace(projectile_scene(), "\"velocity\": [2, 3]", "\"velocity\": [2, -1e400]"),
                   "at /bodies/0/velocity/1: number out of range");
}

TEST(InputFaults, NestingTooDeepIsAnErrorNotAStackOverflow) {
  const std::string deep = std::string(100000, '[') + "1" + std::string(100000, ']');
  // The pointer of the first value too deep: 64 levels are allowed (mass is level 3).
  std::string pointer = "/bodies/0/mass";
  for (int level = 4; level <= 64; ++level) pointer += "/0";
  expect_bad_input("deep", replace(projectile_scene(), "\"mass\": 2.0", "\"mass\": " + deep),
                   "at " + pointer + ": objects and arrays nested more than 64 levels deep");
}

TEST(InputFaults, AGroupThatIsNotAStringIsAValidationError) {
  const std::string scene = R"({
  "format": "moreau-scene/1", "dimension": 2, "time": {"step": 0.01, "duration": 0.1},
  "laws": {"l": {"type": "coulomb", "friction": 0.3}},
  "bodies": [{"name": "a", "mass": 1, "inertia": 1, "contactors": [{"shape": "disk", "radius": 0.1, "group": 7}]},
             {"name": "b", "mass": 1, "inertia": 1, "position": [1, 0], "contactors": [{"shape": "disk", "radius": 0.1}]}],
  "interactions": [{"groups": ["default", "default"], "law": "l"}]
})";
  expect_bad_input("group", scene, "at /bodies/0/contactors/0/group: expected a string, got an integer");
}

TEST(InputFaults, AnEmptyOutputFileNameIsAnError) {
  expect_bad_input("empty_out", replace(projectile_scene(), "\"file\": \"out.h5\"", "\"file\": \"\""),
                   "at /output/file: expected a file name, got an empty string");
  const fs::path dir = scratch_dir("empty_out_cli");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  Result r = run_moreau({"run", scene.string(), "--out", ""}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--out: expected a file name"), std::string::npos) << r.err;
}

TEST(InputFaults, ADuplicatedKeyInAParamValueIsRefused) {
  const fs::path dir = scratch_dir("param_dup");
  Result r = run_moreau({"fclib", "solve", std::string(MOREAU_SHARED_DIR) + "/fclib/fclib-local_problem_test.hdf5",
                         "--solver", "nlgs", "--param", "ordering={\"a\": 1, \"a\": 2}"}, dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--param ordering: at /a: duplicate key \"a\""), std::string::npos) << r.err;
}

TEST(InputFaults, AClosedOutputPipeDoesNotKillMoreau) {
  // `moreau plugins | head -1`: writes to a pipe nobody reads end in a failed write, not SIGPIPE.
  const fs::path dir = scratch_dir("pipe");
  write_file(dir, "pipe.sh",
             "'" MOREAU_EXE "' plugins --json | true\necho \"${PIPESTATUS[0]}\" > '" + (dir / "code").string() + "'\n");
  ASSERT_EQ(std::system(("bash '" + (dir / "pipe.sh").string() + "'").c_str()), 0);
  std::ifstream in(dir / "code");
  int code = -1;
  in >> code;
  EXPECT_NE(code, 128 + 13) << "killed by SIGPIPE";
}
