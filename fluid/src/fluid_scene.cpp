#include "fluid_scene.hpp"

#include <algorithm>
#include <cmath>

#include "equation_of_state.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/lattice.hpp"
#include "sphcore/region_reader.hpp"

namespace cosph::fluid {
namespace {

using Box = cosph::config::Box;

bool overlaps(const Box& a, const Box& b, double tolerance) {
  return a.min().x() < b.max().x() - tolerance && b.min().x() < a.max().x() - tolerance &&
         a.min().y() < b.max().y() - tolerance && b.min().y() < a.max().y() - tolerance;
}

// Is there a box beyond point p in direction (dx, dy), one of (+-1, 0), (0, -1)?
bool closed_towards(const std::vector<Box>& closers, const Vec2& p, int dx, int dy, double eps) {
  for (const Box& b : closers) {
    const bool spans_x = b.min().x() - eps <= p.x() && p.x() <= b.max().x() + eps;
    const bool spans_y = b.min().y() - eps <= p.y() && p.y() <= b.max().y() + eps;
    if (dy < 0 && spans_x && b.max().y() <= p.y() + eps) return true;
    if (dx < 0 && spans_y && b.max().x() <= p.x() + eps) return true;
    if (dx > 0 && spans_y && b.min().x() >= p.x() - eps) return true;
  }
  return false;
}

// A wall particle deep inside the walls, with nothing but wall within the
// kernel support around it, can never meet water: it is left out, so that thick
// walls cost nothing at fine resolutions.
bool within_reach_of_water(const google::protobuf::RepeatedPtrField<Box>& walls, const Vec2& x,
                           const FluidParameters& p) {
  const double reach = sph::kernel::kSupport * p.h, step = 0.5 * p.dx;
  const int samples = static_cast<int>(std::ceil(reach / step));
  for (int i = -samples; i <= samples; ++i)
    for (int j = -samples; j <= samples; ++j) {
      const Vec2 offset(i * step, j * step);
      if (offset.norm() > reach) continue;
      const Vec2 probe = x + offset;
      if (std::none_of(walls.begin(), walls.end(),
                       [&](const Box& wall) { return sph::contains(wall, probe); }))
        return true;
    }
  return false;
}

// The box around a moving wall where it is drawn: what the leak and overlap
// checks see of it (the water must be closed at the start).
std::vector<Box> moving_wall_bounds(const sph::CaseFile& case_file) {
  std::vector<Box> boxes;
  const auto& walls = case_file.config.fluid().moving_walls();
  for (int k = 0; k < walls.size(); ++k) {
    const sph::Bounds b = sph::read_region(walls[k].region(), case_file,
                                           "fluid.moving_walls[" + std::to_string(k) + "].region")
                              .bounds();
    Box& box = boxes.emplace_back();
    box.mutable_min()->set_x(b.min.x());
    box.mutable_min()->set_y(b.min.y());
    box.mutable_max()->set_x(b.max.x());
    box.mutable_max()->set_y(b.max.y());
  }
  return boxes;
}

}  // namespace

void check_walls_close(const sph::CaseFile& case_file, const FluidParameters& parameters) {
  const auto& fluid = case_file.config.fluid();
  std::vector<Box> solid_bodies;
  if (case_file.config.has_solid())
    solid_bodies.assign(case_file.config.solid().body().begin(),
                        case_file.config.solid().body().end());
  std::vector<Box> closers(fluid.walls().begin(), fluid.walls().end());
  closers.insert(closers.end(), solid_bodies.begin(), solid_bodies.end());
  const std::vector<Box> moving_walls = moving_wall_bounds(case_file);
  closers.insert(closers.end(), moving_walls.begin(), moving_walls.end());
  const double dx = parameters.dx, eps = 1e-3 * dx;

  for (int k = 0; k < fluid.water_size(); ++k) {
    const Box& water = fluid.water(k);
    const std::string name = "fluid.water[" + std::to_string(k) + "]";
    for (int w = 0; w < fluid.walls_size(); ++w)
      sph::require(!overlaps(fluid.walls(w), water, eps), case_file,
                   "fluid.walls[" + std::to_string(w) + "]", "overlaps " + name);
    for (std::size_t w = 0; w < moving_walls.size(); ++w)
      sph::require(!overlaps(moving_walls[w], water, eps), case_file,
                   "fluid.moving_walls[" + std::to_string(w) + "]", "overlaps " + name);
    // Two phases on one site: the coupler's pair forces would tear them apart
    // at the first step, and the water would stay inside the solid's shape.
    for (std::size_t b = 0; b < solid_bodies.size(); ++b)
      sph::require(!overlaps(solid_bodies[b], water, eps), case_file,
                   "solid.body[" + std::to_string(b) + "]", "overlaps " + name);
    auto fail = [&](const Vec2& p, const char* side) {
      sph::require(false, case_file, "fluid.walls",
                   "do not close " + name + ": water at (" + sph::format_number(p.x()) + ", " +
                       sph::format_number(p.y()) + ") m can flow out " + side);
    };
    for (double x = water.min().x() + 0.5 * dx; x < water.max().x(); x += dx)
      if (!closed_towards(closers, Vec2(x, water.min().y()), 0, -1, eps))
        fail(Vec2(x, water.min().y()), "through the bottom");
    for (double y = water.min().y() + 0.5 * dx; y < water.max().y(); y += dx) {
      if (!closed_towards(closers, Vec2(water.min().x(), y), -1, 0, eps))
        fail(Vec2(water.min().x(), y), "to the left");
      if (!closed_towards(closers, Vec2(water.max().x(), y), 1, 0, eps))
        fail(Vec2(water.max().x(), y), "to the right");
    }
  }
}

FluidParticles build_fluid_scene(const sph::CaseFile& case_file, const FluidParameters& p) {
  check_walls_close(case_file, p);
  const auto& fluid = case_file.config.fluid();
  const TaitEquationOfState eos(p.rho0, p.c0);
  const double area = p.dx * p.dx;
  const double g = p.run.gravity.norm();
  FluidParticles particles;
  int next_id = 0;
  // Water starts in hydrostatic balance, so that a still tank stays still and a
  // dam break starts without a pressure wave from a uniform density.
  for (const auto& box : fluid.water()) {
    for (const Vec2& x : sph::fill_box(box, p.dx)) {
      const double depth = box.max().y() - x.y();
      const double rho = eos.density(p.rho0 * g * depth);
      particles.add(next_id++, Kind::water, x, rho, rho * area);
    }
  }
  for (const auto& box : fluid.walls()) {
    particles.first_wall_id.push_back(next_id);
    for (const Vec2& x : sph::fill_box(box, p.dx))
      if (within_reach_of_water(fluid.walls(), x, p))
        particles.add(next_id++, Kind::wall, x, p.rho0, p.rho0 * area);
  }
  particles.fixed_walls = particles.first_wall_id.size();
  // A moving wall keeps its particles within 2h of its own surface: it moves
  // rigidly, so the others can never meet water.
  const double reach = sph::kernel::kSupport * p.h;
  for (int k = 0; k < fluid.moving_walls_size(); ++k) {
    const sph::Shape shape =
        sph::read_region(fluid.moving_walls(k).region(), case_file,
                         "fluid.moving_walls[" + std::to_string(k) + "].region");
    particles.first_wall_id.push_back(next_id);
    for (const Vec2& x : sph::fill(shape, p.dx))
      if (shape.depth(x) < reach)
        particles.add(next_id++, Kind::moving_wall, x, p.rho0, p.rho0 * area);
  }
  particles.resize_derived();
  return particles;
}

}  // namespace cosph::fluid
