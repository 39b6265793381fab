#pragma once
// The HDF5 output file of a run (docs/output.md, `format = "moreau-output/2"`), with the
// ParaView description (XDMF) beside it. What is written is the State's field tables:
// every set's constant fields in /<set>/, its frame fields in /frames/N/<set>/; a scene
// whose bodies are all of one one-node modelization (rigid-only scenes) also has them where
// moreau-output/1 put them (/bodies/<field>, /frames/N/<field>), as second names of the
// same datasets (HDF5 hard links: nothing is stored twice).
//
// Crash safety. HDF5 updates a file in place through many metadata blocks, so a process
// killed during a write can leave a file that no longer opens. The writer therefore never
// modifies a file that is visible under its final name:
//  - while the run goes on, each frame is written to its own file in OUT.h5.frames/
//    (under a temporary name, renamed once closed), and OUT.h5 is a small file holding the
//    header and, under /frames, external links to the frame files (and /display, the
//    constant display meshes, links to OUT.h5.frames/display.h5); it is rewritten under a
//    temporary name and renamed over the old one (rename is atomic), so a reader sees the
//    old or the new list, never half of one;
//  - when the run ends (or stops on an error), the frames are copied into one
//    self-contained OUT.h5 (again renamed into place) and the folder is removed.
// A killed run thus leaves OUT.h5 and OUT.h5.frames/: together they read as one file
// (h5py, ParaView and `--restart` follow the links); every frame listed is complete.
// The list of frames is rewritten at most as often as keeps its cost under a tenth of
// the run time, so a kill loses at most the last few seconds of frames.
// A run whose writes fail (a full disk, a file-size limit) ends the same way, with no
// temporary file left: OUT.h5 then lists every complete frame. Frame and list files are
// built in memory and written with write(2) (h5.hpp: a failed H5Fclose leaves HDF5 1.10
// unusable); only the gathered file is written by HDF5.
// OUT.h5.lock (output_lock.hpp) keeps a second run from writing the same file.
//
// Frames are written at stage `output`, after `end_step` swapped the time depths: the
// step's final values are in Depth::begin.
#include <array>
#include <memory>
#include <moreau/state.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "display.hpp"

namespace moreau::io {

/// One contactor of the scene, for readers (`/contactors` of the header): its body, shape
/// and placement in the body frame of the output (whose origin is the centre of mass).
struct ContactorInfo {
  int body = -1;
  int model = 0;         ///< its body's modelization (index into State::models())
  std::size_t node = 0;  ///< its supporting node: row of the modelization's node set
  int local_node = 0;    ///< the same node counted within its body (the scene's `node`)
  std::string shape, group;
  std::array<double, 3> offset{0, 0, 0};
  std::array<double, 4> rotation{1, 0, 0, 0};  ///< 2D: angle in [0]; 3D: unit quaternion w x y z
  /// How far the shape reaches from its node (m): |offset| + the radius of its bounds at
  /// the identity pose; infinite for a half-space. The force network's lines end at the
  /// contact point on the side of a node far larger than its partner (force_network.hpp).
  double reach = 0;
};

/// A modelization's element topology for readers and the viewer: `/<set>/cells`.
struct SetTopology {
  std::string elements;   ///< the element set
  std::string nodes;      ///< the node set its cells index
  std::vector<int> cells; ///< XDMF Mixed connectivity over the node set's rows
  std::size_t count = 0;  ///< cells
};

struct OutputHeader {
  int dimension = 3;
  double time_step = 0;
  std::string scene_text;  ///< the scene JSON, verbatim
  std::vector<ContactorInfo> contactors;  ///< every contactor, in scene order
  std::vector<SetTopology> topologies;    ///< modelizations with elements
  /// The shapes drawn in the viewer (`/display`, and display/points in every frame); null
  /// with output `display: "points"`. Shared: it can be large and the writer only reads it.
  std::shared_ptr<const DisplayMeshes> display;
};

/// A named dataset added to a frame by a producer other than the State (analyses): written
/// at /frames/NNNNNNNN/<group path>/<name>; `name` may hold '/' (subgroups). Numbers
/// (`values`, row-major in `shape`; empty shape: a scalar) or strings (1-D).
struct FrameDataset {
  std::string name;
  std::vector<std::size_t> shape;
  std::vector<double> values;
  std::vector<std::string> strings;
  std::string units;  ///< the dataset's `units` attribute, if not empty
};

/// A group of such datasets (e.g. "analyses/stress"), with string attributes.
struct FrameGroup {
  std::string path;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<FrameDataset> datasets;
};

class OutputWriter {
 public:
  /// A new file (replacing any file at `path`). Unwritable path, or another run writing
  /// `path` (OUT.h5.lock): InputError naming it. A write failing at the start (a full
  /// disk): RunError with the OS's reason, nothing left behind.
  static std::unique_ptr<OutputWriter> create(const std::string& path, const OutputHeader& header, const State& state);
  /// An existing output file of the same scene, to continue after frame `after_step`:
  /// later frames are dropped. Same errors.
  static std::unique_ptr<OutputWriter> append(const std::string& path, const OutputHeader& header, const State& state,
                                              long after_step);
  /// Without close(), the frames written so far are still gathered into one file.
  ~OutputWriter();

  // A write that fails (a full disk, a file-size limit: RunError naming the file and the
  // OS's reason) ends the writer: no temporary file is left, and OUT.h5 lists every
  // complete frame with OUT.h5.frames/ beside it, as after a killed run (the message says
  // how to continue). No later call writes anything.

  /// `extra`: groups added to the frame (analyses), written after the State's sets.
  void write_frame(long step, double time, const State& state, long solver_iterations, double solver_error,
                   const std::vector<FrameGroup>& extra = {});
  /// A new file's first frame copied as it is from frame `step` of output file `source`: a
  /// restart into a new file starts with its restart frame, contacts and solver figures
  /// included, bit-identical to the uninterrupted run's (they cannot be recomputed without
  /// the step before it). False (nothing done) when `source` is of an earlier format,
  /// whose frames would mix layouts here: the caller writes the first frame itself.
  bool copy_first_frame(const std::string& source, long step);
  void close();

  const std::string& path() const;

 private:
  struct Impl;
  explicit OutputWriter(std::unique_ptr<Impl> impl);
  void write_frame_file(long step, double time, const State& state, long solver_iterations, double solver_error,
                        const std::vector<FrameGroup>& extra);
  std::unique_ptr<Impl> impl_;
};

/// Frame names are the step number, zero-padded to 8 digits.
std::string frame_name(long step);
/// The step of a frame name; nullopt when `name` is not one (a damaged or foreign file).
std::optional<long> frame_step(const std::string& name);

/// The folder holding one file per frame while a run writes OUT.h5: OUT.h5.frames.
std::string frames_folder(const std::string& h5_path);

/// The output format this moreau writes, and the one before it (still read: restart).
inline constexpr const char* output_format = "moreau-output/2";
inline constexpr const char* output_format_v1 = "moreau-output/1";

/// Whether the state's bodies are exactly the rows of one modelization's node set (one
/// node each, in body order: rigid-only scenes): its fields are then also written where
/// moreau-output/1 had them. Returns that node set, or "".
std::string legacy_node_set(const State& state);

}  // namespace moreau::io
