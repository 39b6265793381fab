#include "output_sink.hpp"

#include <moreau/error.hpp>

#include "../io/output_writer.hpp"
#include "../contact/contact_stages.hpp"
#include "../io/restart.hpp"

namespace moreau::kernel {

namespace {

class Hdf5Sink : public FrameSink {
 public:
  explicit Hdf5Sink(std::unique_ptr<io::OutputWriter> w) : w_(std::move(w)) {}
  void write_frame(long step, double time, const State& state, const SolverInfo& solver,
                   const std::vector<io::FrameGroup>& extra) override {
    w_->write_frame(step, time, state, solver.iterations, solver.error, extra);
  }
  void close() override { w_->close(); }

 private:
  std::unique_ptr<io::OutputWriter> w_;
};

}  // namespace

std::unique_ptr<FrameSink> open_output(const World& world, const std::string& path, std::optional<long> continue_after) {
  io::OutputHeader header{world.dimension, world.h, world.scene_text, world.contactor_info, world.topologies, world.display};
  if (continue_after)
    return std::make_unique<Hdf5Sink>(io::OutputWriter::append(path, header, world.state, *continue_after));
  return std::make_unique<Hdf5Sink>(io::OutputWriter::create(path, header, world.state));
}

long load_restart(World& world, const std::string& file, std::optional<long> frame) {
  const io::RestartFrame r = io::read_restart(file, frame, world.state);
  if (world.contacts) world.contacts->restored();
  return r.step;
}

}  // namespace moreau::kernel
