// Datasets of strings (names, analyses' column names) are written and read with a transfer
// buffer sized to them (kernel/io/h5.cpp: strings_transfer), in one pass up to 32768
// strings and in several beyond. Whatever the count and length, what is read back, from
// memory and from the file on disk, is what was written, in a variable-length UTF-8 dataset.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "kernel/io/h5.hpp"

namespace h5 = moreau::io::h5;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> strings(std::size_t n, std::size_t length) {
  std::vector<std::string> v;
  for (std::size_t i = 0; i < n; ++i) {
    std::string s = "é" + std::to_string(i);  // UTF-8, and each one different
    while (s.size() < length) s += static_cast<char>('a' + (s.size() + i) % 26);
    v.push_back(s);
  }
  return v;
}

}  // namespace

TEST(H5Strings, ReadBackAsWrittenWhateverTheirCount) {
  const fs::path dir = fs::temp_directory_path() / ("moreau_h5_strings_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "strings.h5").string();
  // Counts around the buffer's size classes (512 B = 16 strings ... 1 MiB = 32768), empty
  // strings, and strings longer than a buffer's share of them.
  const std::vector<std::pair<std::size_t, std::size_t>> cases = {
      {1, 0}, {1, 3}, {15, 8}, {16, 8}, {17, 8}, {1000, 40}, {32768, 12}, {32769, 12}, {70000, 5}, {3, 5000}};
  {
    h5::MemoryFile f(path);
    ASSERT_TRUE(f);
    for (const auto& [n, length] : cases) {
      const std::string name = std::to_string(n) + "x" + std::to_string(length);
      h5::write_strings(f.get(), name, strings(n, length));
      EXPECT_EQ(h5::read_strings(f.get(), name, path), strings(n, length)) << name << " in memory";
    }
    f.save(path);
  }
  h5::Id f = h5::file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  ASSERT_TRUE(f);
  for (const auto& [n, length] : cases) {
    const std::string name = std::to_string(n) + "x" + std::to_string(length);
    EXPECT_EQ(h5::read_strings(f.get(), name, path), strings(n, length)) << name << " on disk";
    h5::Id d = h5::dataset(H5Dopen2(f.get(), name.c_str(), H5P_DEFAULT));
    h5::Id t = h5::type(H5Dget_type(d.get()));
    EXPECT_EQ(H5Tget_class(t.get()), H5T_STRING) << name;
    EXPECT_GT(H5Tis_variable_str(t.get()), 0) << name;
    EXPECT_EQ(H5Tget_cset(t.get()), H5T_CSET_UTF8) << name;
  }
  f.reset();
  fs::remove_all(dir);
}
