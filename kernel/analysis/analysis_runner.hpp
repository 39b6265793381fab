#pragma once
// The scene's analyses (key `analyses`, docs/analyses.md): each runs at every `every`-th
// output frame on its region and adds a group /frames/NNNNNNNN/analyses/<name>/ to the
// frame; those that ask for it also see every step (AnalysisRunner::after_step).
#include <memory>
#include <moreau/analysis.hpp>
#include <string>
#include <vector>

#include "../io/output_writer.hpp"
#include "../plugin/owned.hpp"

namespace moreau::kernel {

struct World;
class FrameView;

/// One entry of the scene's `analyses`.
struct AnalysisUse {
  std::string name;     ///< its group in the frame (default: the plugin name)
  std::string type;     ///< the plugin
  std::string pointer;  ///< /analyses/i
  Region region;
  long every = 1;       ///< runs at every N-th output frame
  Owned<Analysis> analysis;
};

class AnalysisRunner {
 public:
  AnalysisRunner(const World& world, std::vector<AnalysisUse> uses);
  ~AnalysisRunner();

  /// After each step (stage output), before the step's frame is written.
  void after_step(const World& world, long steps_done);
  /// At an output frame: the groups of the analyses due at it.
  std::vector<io::FrameGroup> at_frame(const World& world, long step);

  const std::vector<AnalysisUse>& uses() const { return uses_; }

 private:
  std::vector<AnalysisUse> uses_;
  std::unique_ptr<FrameView> view_;
  bool every_step_ = false;
  long frames_ = 0;  ///< output frames seen, for `every`
  bool stepped_ = false;  ///< a step ran: frames from now on follow a step
};

}  // namespace moreau::kernel
