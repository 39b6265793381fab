#include <filesystem>
#include <moreau/error.hpp>

#include "fclib.hpp"
#include "h5.hpp"

namespace moreau::fclib {

void write_solution(const std::string& path, const Eigen::VectorXd& r, const Eigen::VectorXd& u, const Eigen::VectorXd* v) {
  namespace h5 = moreau::io::h5;
  h5::quiet();
  const std::string tmp = path + ".tmp";
  {
    h5::Id f = h5::file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    if (!f) throw InputError("", "cannot create the solution file", path);
    h5::Id g = h5::group(H5Gcreate2(f.get(), "solution", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    h5::write_doubles(g.get(), "r", r.data(), static_cast<hsize_t>(r.size()), 0);
    h5::write_doubles(g.get(), "u", u.data(), static_cast<hsize_t>(u.size()), 0);
    if (v) h5::write_doubles(g.get(), "v", v->data(), static_cast<hsize_t>(v->size()), 0);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw RunError("cannot move the solution into place at " + path + ": " + ec.message());
}

}  // namespace moreau::fclib
