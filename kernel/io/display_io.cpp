#include "display_io.hpp"

#include <moreau/error.hpp>

#include "node_poses.hpp"

namespace moreau::io {

void write_display_header(hid_t root, const DisplayMeshes& m) {
  const int d = m.dimension;
  const std::size_t nv = m.vertices();
  std::vector<double> points(nv * d);  // d columns on file, like every other [n, d] dataset
  for (std::size_t v = 0; v < nv; ++v)
    for (int k = 0; k < d; ++k) points[d * v + k] = m.points[3 * v + k];
  h5::Id g = h5::group(H5Gcreate2(root, "display", H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
  if (!g) throw RunError("HDF5 write failed: group /display");
  h5::attribute_long(g.get(), "cells", static_cast<long>(m.cell_count()));
  h5::write_doubles(g.get(), "points", points.data(), nv, d);
  h5::write_int32(g.get(), "point_body", m.point_body.data(), nv, 0);
  h5::write_int32(g.get(), "cells", m.cells.data(), m.cells.size(), 0);
  h5::write_int32(g.get(), "cell_body", m.cell_body.data(), m.cell_count(), 0);
  h5::write_int32(g.get(), "cell_contactor", m.cell_contactor.data(), m.cell_count(), 0);
}

void write_display_frame(hid_t frame, const DisplayMeshes& m, const State& state) {
  const int d = m.dimension;
  NodePoses poses;
  node_poses(state, Depth::begin, poses);
  std::vector<float> world;
  world_points(m, poses.size(), poses.position.data(), poses.rotation.data(), world);
  h5::Id g = h5::group(H5Gcreate2(frame, "display", H5P_DEFAULT, h5::group_creation(), H5P_DEFAULT));
  if (!g) throw RunError("HDF5 write failed: group display");
  h5::write_floats(g.get(), "points", world.data(), m.vertices(), d);
}

}  // namespace moreau::io
