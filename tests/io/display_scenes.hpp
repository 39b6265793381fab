#pragma once
// Scenes whose bodies are drawn as shapes (output `display`), for the display and viewer
// description tests, and HDF5 helpers to inspect what they write.
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace moreau_test {

/// 2D: a segment floor, a disk (rotated, on the floor), a square polygon, a cluster of two
/// disks in the air; interactions, so frames after the first hold contacts.
inline std::string display_scene_2d(const std::string& display = "shapes") {
  return R"({"format": "moreau-scene/1", "dimension": 2,
  "time": {"step": 0.001, "duration": 0.01}, "gravity": [0, -9.81],
  "materials": {"m": {"density": 1000}},
  "laws": {"l": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, 0],
     "contactors": [{"shape": "segment", "length": 4, "thickness": 0.1, "group": "wall"}]},
    {"name": "wheel", "material": "m", "position": [1, 0.15], "angle": 0.3,
     "contactors": [{"shape": "disk", "radius": 0.1, "group": "grain"}]},
    {"name": "block", "material": "m", "position": [-1, 0.15],
     "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]], "group": "grain"}]},
    {"name": "pair", "material": "m", "position": [0, 1], "angle": 0.2,
     "contactors": [{"shape": "disk", "radius": 0.05, "offset": [-0.05, 0], "group": "grain"},
                    {"shape": "disk", "radius": 0.05, "offset": [0.05, 0], "group": "grain"}]}
  ],
  "interactions": [{"groups": ["grain", "wall"], "law": "l"}],
  "output": {"file": "out.h5", "every": 5, "display": ")" +
         display + R"("}})";
}

/// 3D: a plane floor, a box turned 0.5 rad about z resting on it, a sphere, a tetrahedron.
inline std::string display_scene_3d(const std::string& display = "shapes") {
  return R"({"format": "moreau-scene/1", "dimension": 3,
  "time": {"step": 0.001, "duration": 0.01}, "gravity": [0, 0, -9.81],
  "materials": {"m": {"density": 1000}},
  "laws": {"l": {"type": "coulomb", "friction": 0.3}},
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, 0, 0],
     "contactors": [{"shape": "plane", "group": "wall"}]},
    {"name": "crate", "material": "m", "position": [1, 2, 0.05],
     "orientation": [0.96891242171064473, 0, 0, 0.24740395925452294],
     "contactors": [{"shape": "box", "size": [0.4, 0.2, 0.1], "group": "grain"}]},
    {"name": "ball", "material": "m", "position": [-1, 0, 0.1],
     "contactors": [{"shape": "sphere", "radius": 0.1, "group": "grain"}]},
    {"name": "gem", "material": "m", "position": [0, -1, 0.5],
     "contactors": [{"shape": "convex", "vertices": [[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]], "group": "grain"}]}
  ],
  "interactions": [{"groups": ["grain", "wall"], "law": "l"}],
  "output": {"file": "out.h5", "every": 5, "display": ")" +
         display + R"("}})";
}

/// A dataset's dimensions, its type class and size in bytes; false if it does not exist.
struct DatasetInfo {
  std::vector<hsize_t> dims;
  H5T_class_t type_class = H5T_NO_CLASS;
  std::size_t type_size = 0;
};

/// Whether a link path exists, level by level (H5Lexists fails on a missing parent).
inline bool h5_exists(hid_t f, const std::string& path) {
  std::string partial;
  for (std::size_t at = 1; at <= path.size();) {
    const std::size_t end = path.find('/', at);
    partial += "/" + path.substr(at, end - at);
    if (H5Lexists(f, partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return true;
}

inline bool dataset_info(hid_t f, const std::string& path, DatasetInfo& out) {
  if (!h5_exists(f, path)) return false;
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (d < 0) return false;
  hid_t s = H5Dget_space(d);
  out.dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(s)), 0);
  H5Sget_simple_extent_dims(s, out.dims.data(), nullptr);
  hid_t t = H5Dget_type(d);
  out.type_class = H5Tget_class(t);
  out.type_size = H5Tget_size(t);
  H5Tclose(t);
  H5Sclose(s);
  H5Dclose(d);
  return true;
}

/// Reads a numeric dataset converted to `mem_type` (H5T_NATIVE_INT, H5T_NATIVE_DOUBLE, …).
template <class T>
std::vector<T> read_as(hid_t f, const std::string& path, hid_t mem_type) {
  hid_t d = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (d < 0) throw std::runtime_error("no dataset " + path);
  hid_t s = H5Dget_space(d);
  std::vector<T> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
  if (!v.empty()) H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(s);
  H5Dclose(d);
  return v;
}

}  // namespace moreau_test
