#pragma once
// The viewer description beside an output file (OUT.xmf next to OUT.h5): an XDMF 3 file
// that ParaView opens directly, reading the arrays from the HDF5 file. Four temporal
// collections (docs/output.md, "Viewer description"):
//  - "bodies": points (position) with velocities, angle/orientation, mass, fixed;
//  - "shapes": each contactor drawn as its shape (output `display: "shapes"`);
//  - "contacts": points with normal, force, normal_force, gap and status (Glyph arrows);
//  - "force_network": one line per contact joining its two bodies' positions, with
//    normal_force, force and status on the lines (Tube, colour by force).
// Every array is a reference into the HDF5 file; nothing is copied.
#include <cstddef>
#include <string>
#include <vector>

namespace moreau::io {

struct XdmfFrame {
  long step;
  double time;
  std::size_t contacts;
  bool display = false;      ///< the frame holds display/points
  bool normal_force = true;  ///< the frame holds contacts/normal_force (not in files before it was added)
};

/// Sizes of the header's /display group (all 0: no shapes grid).
struct XdmfDisplay {
  std::size_t vertices = 0;      ///< rows of /display/points and of each frame's display/points
  std::size_t cells = 0;         ///< cells of the Mixed topology
  std::size_t connectivity = 0;  ///< length of /display/cells
};

/// Path of the description for an output file: OUT.h5 → OUT.xmf.
std::string xdmf_path(const std::string& h5_path);

/// Writes the description (to a temporary file, then renamed over the old one).
void write_xdmf_file(const std::string& h5_path, int dimension, const std::vector<XdmfFrame>& frames,
                     std::size_t bodies, const XdmfDisplay& display = {});

}  // namespace moreau::io
