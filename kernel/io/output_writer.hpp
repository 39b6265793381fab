#pragma once
// The HDF5 output file of a run (DESIGN §3.3, `format = "moreau-output/1"`), with the
// ParaView description (XDMF) beside it.
//
// Crash safety: a frame becomes visible in one step. It is written, with every dataset,
// into the file, then the file is flushed; only then is its name linked under /frames,
// and the file flushed again. HDF5's metadata cache is set to keep metadata in memory
// between flushes, so a process killed at any moment leaves on disk the file of the
// last flush: every visible frame is complete. The file uses the 1.8 format (no
// superblock status flags, so a killed run's file opens without h5clear).
//
// Frames are written at stage `output`, after `end_step` swapped the time depths: the
// step's final values are in Depth::begin.
#include <memory>
#include <moreau/state.hpp>
#include <optional>
#include <string>
#include <vector>

namespace moreau::io {

struct OutputHeader {
  int dimension = 3;
  double time_step = 0;
  std::string scene_text;  ///< the scene JSON, verbatim
};

/// The contacts of a frame (DESIGN §3.3), nc rows each.
struct ContactFrame {
  std::vector<int> bodies;          ///< nc × 2
  std::vector<double> point;        ///< nc × d
  std::vector<double> normal;       ///< nc × d
  std::vector<double> gap;          ///< nc
  std::vector<double> impulse;      ///< nc × d, local frame, normal first
  std::vector<double> force;        ///< nc × d, world frame
  std::vector<signed char> status;  ///< nc: 0 open, 1 sticking, 2 sliding
  std::vector<int> keys;            ///< nc × 3: contactor, contactor, feature (warm start on restart)
  std::size_t size() const { return gap.size(); }
};

class OutputWriter {
 public:
  /// A new file (replacing any file at `path`). Unwritable path: InputError naming it.
  static std::unique_ptr<OutputWriter> create(const std::string& path, const OutputHeader& header, const State& state);
  /// An existing output file of the same scene, to continue after frame `after_step`:
  /// later frames are unlinked.
  static std::unique_ptr<OutputWriter> append(const std::string& path, const OutputHeader& header, const State& state,
                                              long after_step);
  ~OutputWriter();

  void write_frame(long step, double time, const State& state, long solver_iterations, double solver_error,
                   const ContactFrame* contacts);
  void close();

  const std::string& path() const;

 private:
  struct Impl;
  explicit OutputWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Frame names are the step number, zero-padded to 8 digits.
std::string frame_name(long step);

}  // namespace moreau::io
