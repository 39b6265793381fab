#include "analysis_runner.hpp"

#include "../run/world.hpp"
#include "frame_view.hpp"

namespace moreau::kernel {

AnalysisRunner::AnalysisRunner(const World& world, std::vector<AnalysisUse> uses)
    : uses_(std::move(uses)), view_(std::make_unique<FrameView>(world)) {
  for (const auto& u : uses_) every_step_ = every_step_ || u.analysis->every_step();
}

AnalysisRunner::~AnalysisRunner() = default;

void AnalysisRunner::after_step(const World& world, long steps_done) {
  stepped_ = true;
  if (!every_step_) return;
  const AnalysisFrame& f = view_->build(world, steps_done, true);
  for (auto& u : uses_)
    if (u.analysis->every_step()) u.analysis->step(f, u.region);
}

std::vector<io::FrameGroup> AnalysisRunner::at_frame(const World& world, long step) {
  std::vector<io::FrameGroup> groups;
  const long index = frames_++;
  const AnalysisFrame* f = nullptr;
  for (auto& u : uses_) {
    if (index % u.every != 0) continue;
    if (!f) f = &view_->build(world, step, stepped_);
    AnalysisResult result;
    u.analysis->run(*f, u.region, result);
    io::FrameGroup g;
    g.path = "analyses/" + u.name;
    g.attributes.emplace_back("type", u.type);
    for (auto& ds : result.datasets)
      g.datasets.push_back(io::FrameDataset{std::move(ds.name), std::move(ds.shape), std::move(ds.values),
                                            std::move(ds.strings), std::move(ds.units)});
    groups.push_back(std::move(g));
  }
  return groups;
}

}  // namespace moreau::kernel
