#pragma once
// The viewer description beside an output file (OUT.xmf next to OUT.h5): an XDMF 3
// temporal collection that ParaView opens directly, reading the arrays from the HDF5
// file. Bodies are points (position) with their velocities as attributes; contacts are a
// second collection of points with normal, force, gap and status.
#include <cstddef>
#include <string>
#include <vector>

namespace moreau::io {

struct XdmfFrame {
  long step;
  double time;
  std::size_t contacts;
};

/// Path of the description for an output file: OUT.h5 → OUT.xmf.
std::string xdmf_path(const std::string& h5_path);

/// Writes the description (to a temporary file, then renamed over the old one).
void write_xdmf_file(const std::string& h5_path, int dimension, const std::vector<XdmfFrame>& frames,
                     std::size_t bodies);

}  // namespace moreau::io
