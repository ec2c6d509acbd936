// Square particle lattices filling the boxes of a case file.
#pragma once

#include <vector>

#include "case.pb.h"
#include "sphcore/types.hpp"

namespace sph {

// Centres of the spacing x spacing cells that tile the box, half a spacing in
// from its edges, so that the particles' own areas tile the box exactly.
std::vector<Vec2> fill_box(const cosph::config::Box& box, double spacing);

bool contains(const cosph::config::Box& box, const Vec2& p);

}  // namespace sph
