#include "libstruct/model/coupled_motion.hpp"

namespace flexmoor::model {

void CoupledMotion::next(const Sample& end) { between(end_, end); }

// The interpolant's coefficients in s = (t - t0) / h: p(0) = x0, p'(0) = h v0, p''(0) = h^2 a0
// and the same at s = 1. With d0, d1, d2 the end conditions less what c0..c2 give there, the
// quintic's top coefficients are c3 = 10 d0 - 4 d1 + d2 / 2, c4 = -15 d0 + 7 d1 - d2,
// c5 = 6 d0 - 3 d1 + d2 / 2; the cubic's (no accelerations) c2 = 3 d0 - d1, c3 = d1 - 2 d0.
void CoupledMotion::between(Sample start, Sample end) {
  start_ = start;
  end_ = end;
  h_ = end.t - start.t;
  for (double& c : c_) c = 0.0;
  c_[0] = start.value;
  if (h_ <= 0.0) return;
  c_[1] = h_ * start.rate;
  if (start.has_acceleration && end.has_acceleration) {
    c_[2] = 0.5 * h_ * h_ * start.acceleration;
    const double d0 = end.value - (c_[0] + c_[1] + c_[2]);
    const double d1 = h_ * end.rate - (c_[1] + 2.0 * c_[2]);
    const double d2 = h_ * h_ * end.acceleration - 2.0 * c_[2];
    c_[3] = 10.0 * d0 - 4.0 * d1 + 0.5 * d2;
    c_[4] = -15.0 * d0 + 7.0 * d1 - d2;
    c_[5] = 6.0 * d0 - 3.0 * d1 + 0.5 * d2;
  } else {
    const double d0 = end.value - c_[0] - c_[1];
    const double d1 = h_ * end.rate - c_[1];
    c_[2] = 3.0 * d0 - d1;
    c_[3] = d1 - 2.0 * d0;
  }
}

double CoupledMotion::polynomial(double s, int order) const {
  double sum = 0.0;
  for (int k = 5; k >= order; --k) {
    double factor = 1.0;  // k (k - 1) ... (k - order + 1)
    for (int j = 0; j < order; ++j) factor *= k - j;
    sum = sum * s + factor * c_[k];
  }
  return sum;
}

double CoupledMotion::value(double t) const {
  if (t >= end_.t) return end_.value;
  if (t <= start_.t || h_ <= 0.0) return start_.value;
  return polynomial((t - start_.t) / h_, 0);
}

double CoupledMotion::rate(double t) const {
  if (t >= end_.t) return end_.rate;
  if (t <= start_.t || h_ <= 0.0) return start_.rate;
  return polynomial((t - start_.t) / h_, 1) / h_;
}

double CoupledMotion::acceleration(double t) const {
  if (t >= end_.t) {
    if (end_.has_acceleration || h_ <= 0.0) return end_.has_acceleration ? end_.acceleration : 0.0;
    return polynomial(1.0, 2) / (h_ * h_);
  }
  if (t <= start_.t || h_ <= 0.0)
    return start_.has_acceleration ? start_.acceleration
           : h_ > 0.0              ? polynomial(0.0, 2) / (h_ * h_)
                                   : 0.0;
  return polynomial((t - start_.t) / h_, 2) / (h_ * h_);
}

}  // namespace flexmoor::model
