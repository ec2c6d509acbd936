// Which kernel a phase's own pairs use (docs/physics.md, "Kernel"): the cubic
// spline (kernel.hpp, the solids' and an option of the water) or the Wendland
// C2 (wendland_kernel.hpp, the water's default). Both have support 2h, so the neighbour search, the
// walls' thickness rule and the cost of a pair are the same for either.
#pragma once

#include "sphcore/kernel.hpp"
#include "sphcore/wendland_kernel.hpp"

namespace sph::kernel {

enum class Shape { cubic_spline, wendland_c2 };

// W(r) of either shape for one fixed h; the branch is the same for every call.
class ShapedValue {
 public:
  ShapedValue(Shape shape, double h) : wendland_(shape == Shape::wendland_c2), cubic_(h), c2_(h) {}

  double operator()(double r) const { return wendland_ ? c2_(r) : cubic_(r); }

 private:
  bool wendland_;
  Value cubic_;
  wendland_c2::Value c2_;
};

// Calls f(gradient_factor) with the GradientFactor of `shape` for h: the pair
// loops are compiled once for each shape, with no branch per pair.
template <class F>
decltype(auto) with_gradient_factor(Shape shape, double h, F&& f) {
  if (shape == Shape::wendland_c2) return f(wendland_c2::GradientFactor(h));
  return f(GradientFactor(h));
}

}  // namespace sph::kernel
