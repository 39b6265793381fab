#pragma once
// The viewer description beside an output file (OUT.xmf next to OUT.h5): an XDMF 3 file
// that ParaView opens directly, reading the arrays from the HDF5 file. Four temporal
// collections (docs/output.md, "Viewer description"):
//  - "bodies": points (position) with velocities, angle/orientation, mass, fixed;
//  - "shapes": each contactor drawn as its shape (output `display: "shapes"`);
//  - "contacts": points with normal, force, normal_force, gap and status (Glyph arrows),
//    and the contact laws' variables (bond, damage, …);
//  - "force_network": one polyline per contact, body centre – contact point – body centre
//    (a far larger body's end is the contact point), with normal_force, force, status and
//    the laws' variables on the lines (Tube, colour or size by force; broken bonds: colour
//    by bond). Files from before contacts/network join the two bodies' positions.
// Every array is a reference into the HDF5 file; nothing is copied.
#include <cstddef>
#include <moreau/state.hpp>
#include <string>
#include <vector>

namespace moreau::io {

struct XdmfFrame {
  long step;
  double time;
  std::size_t contacts;
  bool display = false;      ///< the frame holds display/points
  bool normal_force = true;  ///< the frame holds contacts/normal_force (not in files before it was added)
  bool network = false;      ///< the frame holds contacts/network (the force network's polylines)
};

/// Sizes of the header's /display group (all 0: no shapes grid).
struct XdmfDisplay {
  std::size_t vertices = 0;      ///< rows of /display/points and of each frame's display/points
  std::size_t cells = 0;         ///< cells of the Mixed topology
  std::size_t connectivity = 0;  ///< length of /display/cells
};

/// What the frames hold beyond moreau-output/1's layout. `legacy`: a rigid-only scene,
/// described as before (a "bodies" grid of points from /frames/N/position). Otherwise one
/// grid per modelization: its nodes (geometry /frames/N/<nodes>/position) as points, or as
/// the cells of its element set (/<elements>/cells) with the element fields on them; the
/// force network joins the bodies' reference points /frames/N/bodies/position.
struct XdmfSet {
  std::string name;  ///< the grid's: the modelization's (ParaView's block selectors do not take dots)
  std::string nodes;
  std::size_t rows = 0;
  std::vector<std::pair<std::string, int>> node_fields;  ///< frame fields: name, components
  std::string elements;                                   ///< "" : points only
  std::size_t cells = 0, connectivity = 0;
  std::vector<std::pair<std::string, int>> element_fields;
};
/// A frame field of the `contacts` set drawn on the contacts and force-network grids
/// beyond the kernel's own: the laws' internal variables (bond, damage, …).
struct XdmfContactField {
  std::string name;
  int components = 1;
  FileType file = FileType::real;
};
struct XdmfLayout {
  bool legacy = true;
  std::vector<XdmfSet> sets;
  std::vector<XdmfContactField> contact_fields;
};
struct SetTopology;
/// The layout of a state's output (`legacy`: the node set of a rigid-only scene, or "").
XdmfLayout xdmf_layout(const State& state, const std::vector<SetTopology>& topologies, const std::string& legacy);

/// Path of the description for an output file: OUT.h5 → OUT.xmf.
std::string xdmf_path(const std::string& h5_path);

/// Writes the description (to a temporary file, then renamed over the old one).
void write_xdmf_file(const std::string& h5_path, int dimension, const std::vector<XdmfFrame>& frames,
                     std::size_t bodies, const XdmfDisplay& display = {}, const XdmfLayout& layout = {});

}  // namespace moreau::io
