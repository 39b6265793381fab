// The plugin loader's error paths (DESIGN §3.4): each failure has its own message.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <moreau/force.hpp>

#include "kernel/plugin/registry.hpp"

namespace fs = std::filesystem;
using moreau::InputError;
using moreau::Kind;
using moreau::kernel::Registry;

namespace {

fs::path plugins(const std::string& sub) { return fs::path(MOREAU_TEST_PLUGINS) / sub; }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.describe();
  }
  return "(no error)";
}

bool mapped(const std::string& needle) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find(needle) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(Loader, FindsAndCreatesByName) {
  Registry reg({plugins("good")});
  auto obj = reg.create<moreau::Force>("good", moreau::Params({{"magnitude", 2.0}}, "/forces/0"), {});
  ASSERT_TRUE(obj);
  EXPECT_EQ(reg.available(Kind::force), std::vector<std::string>{"good"});
}

TEST(Loader, UnknownNameListsValidNames) {
  Registry reg({plugins("good"), plugins("dup")});
  const std::string msg = error_of([&] { reg.require(Kind::force, "nope", "/forces/0/type"); });
  EXPECT_NE(msg.find("at /forces/0/type"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown force 'nope'; valid names: dupa, dupb, good"), std::string::npos) << msg;
  EXPECT_NE(msg.find("libmoreau_force_nope.so"), std::string::npos) << msg;
}

TEST(Loader, FailedToLoadGivesTheLoadersMessage) {
  const fs::path dir = fs::temp_directory_path() / "moreau_test_broken";
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "libmoreau_force_broken.so");
    for (int i = 0; i < 100; ++i) f << "this is not an ELF file\n";
  }
  const std::string msg = error_of([&] { moreau::kernel::LoadedLibrary::open(dir / "libmoreau_force_broken.so"); });
  EXPECT_NE(msg.find("failed to load plugin library"), std::string::npos) << msg;
  EXPECT_NE(msg.find("libmoreau_force_broken.so"), std::string::npos) << msg;
  // dlopen's own words for a non-ELF file
  EXPECT_NE(msg.find("invalid ELF header"), std::string::npos) << msg;
}

TEST(Loader, NoManifest) {
  const std::string msg = error_of([&] { Registry({plugins("nomanifest")}).require(Kind::force, "nomanifest"); });
  EXPECT_NE(msg.find("not a moreau plugin: the library exports no 'moreau_plugin_manifest' entry point"),
            std::string::npos) << msg;
}

TEST(Loader, AbiMismatchNamesBothVersions) {
  const std::string msg = error_of([&] { Registry({plugins("abi")}).require(Kind::force, "abi"); });
  EXPECT_NE(msg.find("plugin ABI mismatch: the library was built for moreau plugin ABI " +
                     std::to_string(MOREAU_ABI_VERSION + 98) + ", this moreau has ABI " +
                     std::to_string(MOREAU_ABI_VERSION)),
            std::string::npos) << msg;
}

TEST(Loader, BuildIdentityMismatch) {
  const std::string msg = error_of([&] { Registry({plugins("build_id")}).require(Kind::force, "buildid"); });
  EXPECT_NE(msg.find("plugin build mismatch: the library was built with 'othercc-1/otherlib'"), std::string::npos) << msg;
}

TEST(Loader, RegisteredNothing) {
  const std::string msg = error_of([&] { Registry({plugins("empty")}).require(Kind::force, "empty"); });
  EXPECT_NE(msg.find("registered nothing"), std::string::npos) << msg;
}

TEST(Loader, FileNameWithoutTheNameItPromises) {
  const std::string msg = error_of([&] { Registry({plugins("misnamed")}).require(Kind::force, "misnamed"); });
  EXPECT_NE(msg.find("registered force 'other' but not force 'misnamed'"), std::string::npos) << msg;
}

TEST(Loader, DuplicateNameNamesBothLibraries) {
  Registry reg({plugins("dup")});
  const std::string msg = error_of([&] { reg.load_all(); });
  EXPECT_NE(msg.find("duplicate plugin name: force 'shared' is registered both by"), std::string::npos) << msg;
  EXPECT_NE(msg.find("libmoreau_force_dupa.so"), std::string::npos) << msg;
  EXPECT_NE(msg.find("libmoreau_force_dupb.so"), std::string::npos) << msg;
}

TEST(Loader, SearchOrderFirstFolderWins) {
  // "good" exists only in plugins("good"); a path listed first without it is skipped,
  // and the library comes from the folder that has it.
  Registry reg({plugins("dup"), plugins("good")});
  const auto& e = reg.require(Kind::force, "good");
  EXPECT_EQ(e.library->path().parent_path(), plugins("good"));
}

TEST(Loader, LibraryStaysLoadedWhileItsObjectsLive) {
  moreau::kernel::Owned<moreau::Force> obj;
  {
    Registry reg({plugins("good")});
    obj = reg.create<moreau::Force>("good", moreau::Params({}, ""), {});
  }  // the registry is gone; the object keeps the library
  EXPECT_TRUE(mapped("libmoreau_force_good.so"));
  obj = {};
  EXPECT_FALSE(mapped("libmoreau_force_good.so"));
}
