#pragma once
// The distance controller's PID (P-CHAN-00821..00823): the output is the
// correction of the offset for this cycle, in mm. kp weights the whole
// output (kp = 1 corrects the full error in one cycle); i_tn is the time
// after which the I share equals the P share, d_tv the time after which the
// D share does; 0 switches either off.
namespace nck::distctrl {

class Pid {
 public:
  void setup(double kp, double i_tn_s, double d_tv_s, double dt_s) noexcept {
    kp_ = kp;
    i_tn_s_ = i_tn_s;
    d_tv_s_ = d_tv_s;
    dt_s_ = dt_s;
  }
  void reset() noexcept {
    integral_ = 0;
    first_ = true;
  }
  double step(double error) noexcept {
    double u = error;
    if (i_tn_s_ > 0) {
      integral_ += error * dt_s_;
      u += integral_ / i_tn_s_;
    }
    if (d_tv_s_ > 0 && !first_) u += d_tv_s_ * (error - last_) / dt_s_;
    last_ = error;
    first_ = false;
    return kp_ * u;
  }

 private:
  double kp_ = 1, i_tn_s_ = 0, d_tv_s_ = 0, dt_s_ = 0.001;
  double integral_ = 0, last_ = 0;
  bool first_ = true;
};

}  // namespace nck::distctrl
