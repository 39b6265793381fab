#include <filesystem>
#include <moreau/error.hpp>

#include "fclib.hpp"
#include "h5.hpp"

namespace moreau::fclib {

void write_solution(const std::string& path, const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd* v) {
  namespace h5 = moreau::io::h5;
  // A folder that does not exist is the user's mistake (exit 2); a failing write is not.
  std::error_code ec;
  const auto folder = std::filesystem::absolute(path, ec).parent_path();
  if (!std::filesystem::is_directory(folder, ec))
    throw InputError("", "cannot create the solution file: its folder " + folder.string() + " does not exist", path);
  h5::MemoryFile f(path);
  if (!f) throw RunError("cannot create the solution file " + path + " in memory");
  {
    h5::Id g = h5::group(H5Gcreate2(f.get(), "solution", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_doubles(g.get(), "r", r.data(), static_cast<hsize_t>(r.size()), 0);
    h5::write_doubles(g.get(), "u", u.data(), static_cast<hsize_t>(u.size()), 0);
    if (v) h5::write_doubles(g.get(), "v", v->data(), static_cast<hsize_t>(v->size()), 0);
  }
  f.save_atomically(path);
}

}  // namespace moreau::fclib
