// Plugins that fail: a constructor or a schema that throws, a static constructor that
// throws while the library loads, an unresolved symbol, exceptions of every kind thrown
// during a run (issue 11). Each ends with a message naming the plugin and exit 2 (the
// plugin refused the scene) or 1 (the run failed), never a signal.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_runner.hpp"
#include "scenes.hpp"

namespace fs = std::filesystem;
using namespace moreau_test;

namespace {

const std::string kFaults = MOREAU_TEST_PLUGINS "/faults";

Result run_with(const std::string& name, const std::string& extra, const std::vector<std::string>& args = {"run"}) {
  const fs::path dir = scratch_dir("plugin_fault_" + name);
  const fs::path scene =
      write_file(dir, "scene.json", projectile_scene(",\n  \"plugin_paths\": [\"" + kFaults + "\"],\n" + extra));
  std::vector<std::string> all = args;
  all.push_back(scene.string());
  if (all.front() == "run") all.push_back("--quiet");
  Result r = run_moreau(all, dir);
  // Bad input leaves no output; a failed run leaves no temporary file.
  EXPECT_FALSE(fs::exists(dir / "out.h5.part"));
  if (r.code == 2) EXPECT_FALSE(fs::exists(dir / "out.h5")) << name;
  return r;
}

void expect_in(const Result& r, const std::string& text) {
  EXPECT_NE(r.err.find(text), std::string::npos) << "missing \"" << text << "\" in:\n" << r.err;
}

}  // namespace

TEST(PluginFaults, ConstructorThrowingAStdExceptionNamesThePlugin) {
  for (const char* cmd : {"check", "run"}) {
    Result r = run_with("ctor", "  \"forces\": [{\"type\": \"ctorthrow\"}]", {cmd});
    EXPECT_EQ(r.code, 2) << r.err;
    expect_in(r, "at /forces/0: the force 'ctorthrow' failed while it was being created: cannot start: "
                 "the frobnicator is missing");
  }
}

TEST(PluginFaults, ConstructorThrowingAnIntNamesThePlugin) {
  Result r = run_with("ctor42", "  \"forces\": [{\"type\": \"ctorthrow42\"}]");
  EXPECT_EQ(r.code, 2) << r.err;
  expect_in(r, "at /forces/0: the force 'ctorthrow42' threw an exception that is not a std::exception");
}

TEST(PluginFaults, SchemaThrowingAtRegistrationIsALoadError) {
  Result r = run_with("schema", "  \"forces\": [{\"type\": \"schemathrow\"}]");
  EXPECT_EQ(r.code, 2) << r.err;
  expect_in(r, "the plugin library failed to register its plugins: force 'schemathrow' threw: schema not written yet");
  expect_in(r, "libmoreau_force_schemathrow.so");
}

TEST(PluginFaults, StaticConstructorThrowingWhileLoadingNamesTheLibrary) {
  Result r = run_with("static", "  \"forces\": [{\"type\": \"staticthrow\"}]");
  EXPECT_EQ(r.code, 2) << r.err;
  expect_in(r, "libmoreau_force_staticthrow.so: the plugin library threw while it was being loaded");
  expect_in(r, "static table: cannot read its data");
}

TEST(PluginFaults, UnresolvedSymbolIsRefusedAtLoadWithTheLoadersMessage) {
  Result r = run_with("unresolved", "  \"forces\": [{\"type\": \"unresolved\"}]");
  EXPECT_EQ(r.code, 2) << r.err;  // not 127 from the loader in the middle of the run
  expect_in(r, "at /forces/0/type: failed to load plugin library");
  expect_in(r, "undefined symbol: moreau_test_function_nobody_defines");
}

TEST(PluginFaults, ExceptionsFromAHookDuringARunAreReportedAfterItsLibraryIsGone) {
  // The exception object is the plugin's; the library unloads with the World while the
  // exception travels: the kernel copies it first, so printing it never runs unmapped code.
  struct Case {
    const char* what;
    int code;
    const char* message;
  };
  const Case cases[] = {
      {"run_error", 1, "run failed: throwing hook: the run cannot go on"},
      {"input_error", 2, "at /hooks/0: throwing hook: bad parameter"},
      {"std", 1, "run failed: the hook 'throwing' (/hooks/0) failed at step 4 (after stage end_step): throwing hook: "
                 "std::runtime_error"},
      {"own", 1, "run failed: the hook 'throwing' (/hooks/0) failed at step 4 (after stage end_step): own error class "
                 "of the plugin"},
      {"int", 1, "run failed: the hook 'throwing' (/hooks/0) threw an exception that is not a std::exception (such as "
                 "`throw 42`) at step 4"},
  };
  for (const auto& c : cases) {
    const fs::path dir = scratch_dir(std::string("hook_") + c.what);
    const fs::path scene = write_file(
        dir, "scene.json",
        projectile_scene(",\n  \"plugin_paths\": [\"" + kFaults + "\"],\n  \"hooks\": [{\"type\": \"throwing\", \"throw\": \"" +
                         c.what + "\"}]"));
    Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
    EXPECT_EQ(r.code, c.code) << c.what << ": " << r.err;
    expect_in(r, c.message);
  }
}

TEST(PluginFaults, TheEnergyLogGivenAnUnwritableFileEndsTheRunCleanly) {
  // The bundled hook throws a RunError from its library at the first step: once a SIGSEGV.
  const fs::path dir = scratch_dir("energy_unwritable");
  const fs::path scene = write_file(
      dir, "scene.json", projectile_scene(",\n  \"hooks\": [{\"type\": \"energy_log\", \"file\": \"no/such/folder/e.csv\"}]"));
  Result r = run_moreau({"run", scene.string(), "--quiet"}, dir);
  EXPECT_EQ(r.code, 1) << r.err;
  expect_in(r, "run failed: energy_log: cannot write");
  EXPECT_TRUE(fs::exists(dir / "out.h5"));  // the frames before the failure, gathered
  EXPECT_FALSE(fs::exists(dir / "out.h5.frames"));
}

TEST(PluginFaults, AMissingPluginFolderInTheSceneIsAnError) {
  const fs::path dir = scratch_dir("missing_plugin_dir");
  const fs::path scene =
      write_file(dir, "scene.json", projectile_scene(",\n  \"plugin_paths\": [\"my_plugins\"]"));
  Result bad = run_moreau({"check", scene.string()}, dir);
  EXPECT_EQ(bad.code, 2) << bad.err;
  expect_in(bad, "at /plugin_paths/0: no folder " + (dir / "my_plugins").string());
}

TEST(PluginFaults, AMissingFolderInMoreauPluginPathIsAWarning) {
  const fs::path dir = scratch_dir("missing_env_dir");
  const fs::path scene = write_file(dir, "scene.json", projectile_scene());
  const std::string before = getenv("MOREAU_PLUGIN_PATH") ? getenv("MOREAU_PLUGIN_PATH") : "";
  setenv("MOREAU_PLUGIN_PATH", "/no/such/moreau/plugins", 1);
  Result r = run_moreau({"check", scene.string()}, dir);
  setenv("MOREAU_PLUGIN_PATH", before.c_str(), 1);
  EXPECT_EQ(r.code, 0) << r.err;
  expect_in(r, "warning: MOREAU_PLUGIN_PATH names \"/no/such/moreau/plugins\", which is not a folder");
}
