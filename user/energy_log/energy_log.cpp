// Example hook `energy_log`: writes the energies of the bodies to a CSV file every N
// steps. Copy this file to start your own hook.
//
//   "hooks": [{"type": "energy_log", "file": "energy.csv", "every": 10}]
//
// Each line is written with one call and flushed, so a run that stops or is killed
// leaves a file of whole lines.
#include <cstdio>
#include <filesystem>
#include <moreau/error.hpp>
#include <moreau/hook.hpp>
#include <moreau/rigid_energy.hpp>

namespace {

using namespace moreau;

class EnergyLog : public Hook {
 public:
  static Schema schema() {
    Schema s;
    s.string("file", "CSV file (relative to the folder of the run's output file)").fallback("energy.csv");
    s.integer("every", "a line every N steps").min(1).fallback(1);
    return s;
  }
  static constexpr const char* doc = "writes kinetic, potential and total energy to a CSV file";

  EnergyLog(const Params& p, const BuildContext& ctx) : every_(p.integer("every")) {
    std::filesystem::path path(p.string("file"));
    if (path.is_relative()) path = std::filesystem::path(ctx.output_dir) / path;
    path_ = path.string();
  }
  ~EnergyLog() override {
    if (out_) std::fclose(out_);
  }

  // After end_step the step's final values are the ⁻ (begin) depth of the next step.
  std::vector<std::pair<Stage, When>> points() const override { return {{Stage::end_step, When::after}}; }

  void run(HookContext& ctx) override {
    const long done = ctx.step() + 1;
    if (!out_) open(ctx);
    if (done % every_ != 0) return;
    write(done * ctx.time_step(), user::energies(ctx.state(), ctx.gravity()));
  }

  void finish(const State&) override {
    if (out_) std::fflush(out_);
  }

 private:
  void open(HookContext& ctx) {
    out_ = std::fopen(path_.c_str(), "w");
    if (!out_) throw RunError("energy_log: cannot write " + path_);
    std::fputs("time,kinetic_translational,kinetic_rotational,potential,total\n", out_);
    // First the state before this run's first step: after end_step swapped the depths,
    // the ⁻ depth holds the step's end values and the ⁺ depth its start values.
    write(static_cast<double>(ctx.step()) * ctx.time_step(), user::energies(ctx.state(), ctx.gravity(), Depth::end));
  }
  void write(double t, const user::Energies& e) {
    char line[256];
    std::snprintf(line, sizeof line, "%.9g,%.12g,%.12g,%.12g,%.12g\n", t, e.translational, e.rotational, e.potential,
                  e.total());
    std::fputs(line, out_);
    std::fflush(out_);
  }

  long every_;
  std::string path_;
  std::FILE* out_ = nullptr;
};

MOREAU_REGISTER(EnergyLog, "energy_log")

}  // namespace

MOREAU_PLUGIN_LIBRARY("moreau_hook_energy_log")
