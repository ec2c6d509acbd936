#include "shell_line.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bending_mode.hpp"
#include "line_kernel.hpp"

namespace cosph::solid::shell {

double ShellLine::phi0() const {
  return std::atan2(tangent.y(), tangent.x());
}

ShellLine read_shell_line(const sph::CaseFile& case_file, double dx) {
  const auto& solid = case_file.config.solid();
  sph::require(solid.body_size() == 1, case_file, "solid.body",
               "the shell model takes exactly one body box (the plate), got " +
                   std::to_string(solid.body_size()));
  const auto& box = solid.body(0);
  sph::require(box.has_min() && box.has_max() && box.subtract().empty(), case_file, "solid.body[0]",
               "the shell model takes a box (min and max) without subtract: it reads the box as a "
               "straight plate");
  const double width = box.max().x() - box.min().x(), height = box.max().y() - box.min().y();
  const bool along_x = width >= height;
  const double length = along_x ? width : height, thickness = along_x ? height : width;
  sph::require(thickness > 0.0, case_file, "solid.body[0]", "must have max > min");
  sph::require(
      thickness <= kMostSpacingsAcross * dx && thickness * kLeastSlenderness <= length, case_file,
      "solid.body[0]",
      "a box " + sph::format_number(width) + " x " + sph::format_number(height) +
          " m is not a thin plate: the shell model reads the box as a plate of thickness its "
          "short side, which must be at most " +
          sph::format_number(kMostSpacingsAcross) + " spacings (" +
          sph::format_number(kMostSpacingsAcross * dx) + " m) and at most 1/" +
          sph::format_number(kLeastSlenderness) +
          " of its long side; use solid.model \"jaumann\" or \"total_lagrangian\" for a "
          "thick body");
  ShellLine line;
  line.tangent = along_x ? Vec2(1.0, 0.0) : Vec2(0.0, 1.0);
  line.start = along_x ? Vec2(box.min().x(), 0.5 * (box.min().y() + box.max().y()))
                       : Vec2(0.5 * (box.min().x() + box.max().x()), box.min().y());
  line.length = length;
  line.thickness = thickness;
  line.count = static_cast<int>(std::max(1L, std::lround(length / dx))) + 1;
  line.ds = length / (line.count - 1);
  return line;
}

namespace {

bool in_a_clamp(const SolidParameters& parameters, const Vec2& x) {
  return std::any_of(parameters.clamps.begin(), parameters.clamps.end(),
                     [&](const sph::Shape& clamp) { return clamp.contains(x); });
}

}  // namespace

ShellParticles build_shell(const sph::CaseFile& case_file, const SolidParameters& parameters,
                           const ShellLine& line, const ShellSection& section) {
  sph::require(!parameters.bending_mode || line.tangent.x() > 0.0, case_file,
               "solid.initial_velocity",
               "the shell starts a bending mode on a horizontal plate only (the mode's speed is "
               "vertical and its shape runs along x)");
  ShellParticles P;
  for (int k = 0; k < line.count; ++k) {
    const double S = k * line.ds;
    const Vec2 X = line.start + S * line.tangent;
    const double V = (k == 0 || k == line.count - 1) ? 0.5 * line.ds : line.ds;
    P.id.push_back(k);
    P.X.push_back(X);
    P.S.push_back(S);
    P.V.push_back(V);
    P.m.push_back(section.mass_per_length() * V);
    P.J.push_back(section.inertia_per_length() * V);
    P.c.push_back(section.sound_speed());
    const bool clamped = in_a_clamp(parameters, X);
    P.clamped.push_back(clamped);
    P.x.push_back(X);
    Vec2 v = Vec2::Zero();
    if (parameters.bending_mode && !clamped) {
      const BendingModeParameters& mode = *parameters.bending_mode;
      const double s = X.x() - mode.root_x;
      if (s > 0.0)
        v.y() = mode.tip_speed * cantilever_mode_shape(s, mode.length) /
                cantilever_mode_shape(mode.length, mode.length);
    }
    P.v.push_back(v);
    P.theta.push_back(0.0);
    P.omega.push_back(0.0);
  }
  P.resize_derived();
  find_line_neighbours(P, parameters.h);
  return P;
}

namespace {

// Free particles and the clamps' faces: those whose strains count.
std::vector<bool> strained_particles(const ShellParticles& P) {
  const std::size_t n = P.size();
  std::vector<bool> strained(n);
  for (std::size_t i = 0; i < n; ++i) {
    bool next_to_free = false;
    for (std::size_t j = 0; j < n; ++j)
      if (!P.clamped[j] && std::abs(P.S[j] - P.S[i]) < 1.5 * std::max(P.V[i], P.V[j]))
        next_to_free = true;
    strained[i] = !P.clamped[i] || next_to_free;
  }
  return strained;
}

}  // namespace

void find_line_neighbours(ShellParticles& P, double h) {
  const double reach = sph::kernel::kSupport * h;
  const std::size_t n = P.size();
  const std::vector<bool> strained = strained_particles(P);
  P.neighbours.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    if (!strained[i]) continue;
    // Moments m_k = sum_j w_ij S_ij^k of the kernel weights w_ij = V_j W_ij.
    double m2 = 0.0, m3 = 0.0, m4 = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      const double S_ij = P.S[j] - P.S[i], r = std::abs(S_ij);
      if (j == i || r >= reach || !strained[j]) continue;
      const double W = line_W(r, h), w = P.V[j] * W;
      P.neighbours[i].push_back({static_cast<int>(j), S_ij, W, w});
      m2 += w * S_ij * S_ij;
      m3 += w * S_ij * S_ij * S_ij;
      m4 += w * S_ij * S_ij * S_ij * S_ij;
    }
    // The least-squares fit f_j - f_i = g S_ij + c S_ij^2 / 2 over the
    // neighbours: g = sum_j G_ij (f_j - f_i), G_ij = w_ij (A S_ij + B S_ij^2).
    const double det = m2 * m4 / 4.0 - m3 * m3 / 4.0;
    const bool fits = det > 1e-12 * m2 * m4;  // two neighbours or more, not all on one point
    const double A = fits ? (m4 / 4.0) / det : 0.0, B = fits ? -(m3 / 2.0) / det / 2.0 : 0.0;
    for (LineNeighbour& b : P.neighbours[i]) b.G *= A * b.S_ij + B * b.S_ij * b.S_ij;
  }
}

}  // namespace cosph::solid::shell
