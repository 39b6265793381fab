#include "output_sink.hpp"

#include <moreau/error.hpp>

#include "../io/output_writer.hpp"
#include "../contact/contact_stages.hpp"
#include "../io/restart.hpp"
#include "../io/restart_check.hpp"

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

std::unique_ptr<FrameSink> open_output_from(const World& world, const std::string& path, const std::string& source,
                                            long step, bool& copied) {
  io::OutputHeader header{world.dimension, world.h, world.scene_text, world.contactor_info, world.topologies, world.display};
  auto writer = io::OutputWriter::create(path, header, world.state);
  copied = writer->copy_first_frame(source, step);
  return std::make_unique<Hdf5Sink>(std::move(writer));
}

long load_restart(World& world, const std::string& file, std::optional<long> frame) {
  const io::RestartFrame r = io::read_restart(file, frame, world.state);
  io::check_restart(file, r, world.state, world.contacts ? world.contacts->contactors.size() : 0);
  if (world.contacts) world.contacts->restored(world.state, r.solver_state);
  return r.step;
}

}  // namespace moreau::kernel
