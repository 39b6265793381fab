#include "restart_check.hpp"

#include <cmath>
#include <limits>
#include <moreau/contact_fields.hpp>
#include <moreau/error.hpp>
#include <moreau/rigid_fields.hpp>

#include "output_writer.hpp"

namespace moreau::io {

void check_restart_field(const Field& field, const std::string& path, const std::string& file) {
  const std::size_t nc = static_cast<std::size_t>(field.components());
  const double* v = field.data(Depth::begin);
  const bool rotation = field.name() == rigid::orientation && nc == 4;
  for (std::size_t r = 0; r < field.rows(); ++r) {
    double n2 = 0;
    for (std::size_t k = 0; k < nc; ++k) {
      const double x = v[r * nc + k];
      if (!std::isfinite(x))
        throw InputError(path, "row " + std::to_string(r) + " is not finite (" + std::to_string(x) + ")", file);
      n2 += x * x;
    }
    if (rotation && std::fabs(std::sqrt(n2) - 1) > 1e-6)
      throw InputError(path, "row " + std::to_string(r) + " is not a unit quaternion (norm " + std::to_string(std::sqrt(n2)) +
                                 ")", file);
  }
}

void check_restart(const std::string& file, const RestartFrame& frame, const State& state, std::size_t contactors) {
  const EntitySet* contacts = state.find_set(sets::contacts);
  if (!contacts || contactors == 0 || contacts->rows() == 0) return;
  const std::string kp = "/frames/" + frame_name(frame.step) + "/" + sets::contacts + "/" + contact_fields::key;
  const double* key = contacts->field(contact_fields::key).data(Depth::begin);
  for (std::size_t a = 0; a < contacts->rows(); ++a)
    for (int k = 0; k < 3; ++k) {
      const double x = key[3 * a + k];
      if (!(x == std::floor(x) && std::fabs(x) <= std::numeric_limits<int>::max()))
        throw InputError(kp, "contact " + std::to_string(a) + ": " + std::to_string(x) +
                                 " is not a contact identity (an integer)", file);
      if (k < 2 && (x < 0 || x >= static_cast<double>(contactors)))
        throw InputError(kp, "contact " + std::to_string(a) + " names contactor " + std::to_string(static_cast<long>(x)) +
                                 "; the scene has " + std::to_string(contactors), file);
    }
}

}  // namespace moreau::io
