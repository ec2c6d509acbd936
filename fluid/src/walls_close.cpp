// The water starts at rest, and left alone it flows down and sideways, never
// up: the walls (and the solid bodies, which hold it until they move) must
// stop it going down, left or right, and may leave the top open. From every
// water particle the check floods the water's lattice, one spacing at a time
// in those three directions, through every step that touches no wall and no
// body. Water that gets past the bounds of the whole scene can flow out; the
// case is refused naming the water particle nearest the opening (the flood
// goes breadth first) and the side the water leaves by.
#include "walls_close.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "sphcore/region_reader.hpp"

namespace cosph::fluid {
namespace {

using sph::Shape;

// Water and a region overlap if a point of the water's lattice four times
// finer than the particles' (`fine_water`) lies inside the region, deeper than
// a thousandth of a spacing: a particle of each on one site, or nearly so.
std::optional<Vec2> overlap(const std::vector<Vec2>& fine_water, const Shape& region, double dx) {
  for (const Vec2& x : fine_water)
    if (region.depth(x) > 1e-3 * dx) return x;
  return std::nullopt;
}

struct Step {
  int di, dj;
  const char* side;  // where water that goes this way out of the scene leaves
};
constexpr Step kSteps[] = {
    {0, -1, "through the bottom"}, {-1, 0, "to the left"}, {1, 0, "to the right"}};

// The first water site (of `sites`, on one lattice of spacing dx) from which
// water can flow out of `bounds` past `closers`, and the way it leaves.
struct Leak {
  Vec2 site;
  const char* side;
};
std::optional<Leak> find_leak(const std::vector<Vec2>& sites,
                              const std::vector<const Shape*>& closers, const sph::Bounds& bounds,
                              double dx) {
  if (sites.empty()) return std::nullopt;
  const Vec2 anchor = sites.front();
  const auto index = [&](double from, double to) {
    return static_cast<long>(std::floor((to - from) / dx));
  };
  // The lattice cells over the bounds, one more on every side.
  const long i0 = index(anchor.x(), bounds.min.x()) - 1, i1 = index(anchor.x(), bounds.max.x()) + 2;
  const long j0 = index(anchor.y(), bounds.min.y()) - 1, j1 = index(anchor.y(), bounds.max.y()) + 2;
  const long ni = i1 - i0 + 1, nj = j1 - j0 + 1;
  // The water site each cell was reached from; -1 not yet reached.
  std::vector<int> origin(static_cast<std::size_t>(ni * nj), -1);
  const auto cell = [&](long i, long j) {
    return static_cast<std::size_t>((j - j0) * ni + (i - i0));
  };
  const auto position = [&](long i, long j) {
    return Vec2(anchor.x() + static_cast<double>(i) * dx, anchor.y() + static_cast<double>(j) * dx);
  };
  std::deque<std::pair<long, long>> front;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    const long i = std::lround((sites[k].x() - anchor.x()) / dx);
    const long j = std::lround((sites[k].y() - anchor.y()) / dx);
    if (origin[cell(i, j)] >= 0) continue;
    origin[cell(i, j)] = static_cast<int>(k);
    front.emplace_back(i, j);
  }
  while (!front.empty()) {
    const auto [i, j] = front.front();
    front.pop_front();
    const Vec2 from = position(i, j);
    for (const Step& step : kSteps) {
      const long i_next = i + step.di, j_next = j + step.dj;
      const Vec2 to = position(i_next, j_next);
      if (std::any_of(closers.begin(), closers.end(),
                      [&](const Shape* closer) { return closer->meets(from, to); }))
        continue;
      const int source = origin[cell(i, j)];
      if (i_next <= i0 || i_next >= i1 || j_next <= j0)
        return Leak{sites[static_cast<std::size_t>(source)], step.side};
      if (origin[cell(i_next, j_next)] >= 0) continue;
      origin[cell(i_next, j_next)] = source;
      front.emplace_back(i_next, j_next);
    }
  }
  return std::nullopt;
}

sph::Bounds bounds_of(const std::vector<const Shape*>& shapes) {
  sph::Bounds all = shapes.front()->bounds();
  for (const Shape* shape : shapes) {
    all.min = all.min.cwiseMin(shape->bounds().min);
    all.max = all.max.cwiseMax(shape->bounds().max);
  }
  return all;
}

std::string at(const Vec2& x) {
  std::ostringstream text;
  text << "(" << sph::format_number(x.x()) << ", " << sph::format_number(x.y()) << ") m";
  return text.str();
}

}  // namespace

void check_walls_close(const sph::CaseFile& case_file, const FluidParameters& parameters) {
  const auto& config = case_file.config;
  std::vector<Shape> bodies;
  if (config.has_solid())
    bodies = sph::read_regions(config.solid().body(), case_file, "solid.body");
  // Moving walls where they are drawn: the water must be closed at the start.
  std::vector<Shape> moving;
  for (int k = 0; k < config.fluid().moving_walls_size(); ++k)
    moving.push_back(sph::read_region(config.fluid().moving_walls(k).region(), case_file,
                                      "fluid.moving_walls[" + std::to_string(k) + "].region"));
  std::vector<const Shape*> closers, everything;
  for (const Shape& wall : parameters.walls) closers.push_back(&wall);
  for (const Shape& body : bodies) closers.push_back(&body);
  for (const Shape& wall : moving) closers.push_back(&wall);
  everything = closers;
  for (const Shape& water : parameters.water) everything.push_back(&water);
  const sph::Bounds scene = bounds_of(everything);
  const double dx = parameters.dx;

  for (std::size_t k = 0; k < parameters.water.size(); ++k) {
    const Shape& water = parameters.water[k];
    const std::string name = "fluid.water[" + std::to_string(k) + "]";
    const std::vector<Vec2> fine_water = sph::fill(water, 0.25 * dx);
    for (std::size_t w = 0; w < parameters.walls.size(); ++w) {
      const auto inside = overlap(fine_water, parameters.walls[w], dx);
      sph::require(!inside, case_file, "fluid.walls[" + std::to_string(w) + "]",
                   "overlaps " + name + ": water at " + (inside ? at(*inside) : "") +
                       " would lie inside it");
    }
    for (std::size_t w = 0; w < moving.size(); ++w) {
      const auto inside = overlap(fine_water, moving[w], dx);
      sph::require(!inside, case_file, "fluid.moving_walls[" + std::to_string(w) + "]",
                   "overlaps " + name + ": water at " + (inside ? at(*inside) : "") +
                       " would lie inside it");
    }
    // Two phases on one site: the coupler's pair forces would tear them apart
    // at the first step, and the water would stay inside the solid's shape.
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const auto inside = overlap(fine_water, bodies[b], dx);
      sph::require(!inside, case_file, "solid.body[" + std::to_string(b) + "]",
                   "overlaps " + name + ": water at " + (inside ? at(*inside) : "") +
                       " would lie inside it");
    }
    if (const auto leak = find_leak(sph::fill(water, dx), closers, scene, dx))
      sph::require(
          false, case_file, "fluid.walls",
          "do not close " + name + ": water at " + at(leak->site) + " can flow out " + leak->side);
  }
}

}  // namespace cosph::fluid
