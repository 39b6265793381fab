#pragma once
// The work of a solver stage, counted in units of one product by W (nnz(W) multiply-adds,
// or its equivalent through the factor H M⁻¹ Hᵀ). `auto` shares work, not wall-clock time,
// between its members: counted work is the same on every run and machine, so the same
// input gives the same decisions and the same output (a restart stays bit-identical).
namespace moreau {

class WorkMeter {
 public:
  /// `max`: the stage's budget (0: none); `total`: where the work is also added (may be null).
  WorkMeter(double max, double* total) : max_(max), total_(total) {}
  void add(double units) {
    spent_ += units;
    if (total_) *total_ += units;
  }
  bool exhausted() const { return max_ > 0 && spent_ >= max_; }

 private:
  double max_, spent_ = 0;
  double* total_;
};

}  // namespace moreau
