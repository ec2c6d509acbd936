#include "reference_configuration.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "clamp_reach.hpp"
#include "solid_scene.hpp"
#include "sphcore/cell_grid.hpp"
#include "sphcore/kernel.hpp"
#include "sphcore/parallel.hpp"
#include "sphcore/renormalisation.hpp"
#include "st_venant_kirchhoff.hpp"

namespace cosph::solid::tl {

namespace kernel = sph::kernel;

Mat2 reference_correction(const Mat2& M) {
  constexpr double kSmallestDeterminant = 1e-6;  // a full support gives det(M) = 1
  const double det = M.determinant();
  if (!(std::abs(det) > kSmallestDeterminant)) return Mat2::Identity();
  return M.inverse();
}

TLParticles build_reference_configuration(const sph::CaseFile& case_file,
                                          const SolidParameters& par) {
  const SolidScene scene = build_solid_scene(case_file, par);
  sph::CellGrid grid;
  grid.build(scene.x, kernel::kSupport * par.h);
  TLParticles P;
  for (const int k : grid.order()) {
    const double K = scene.K[k], G = scene.G[k];
    P.id.push_back(scene.id[k]);
    P.X.push_back(scene.x[k]);
    P.x.push_back(scene.x[k]);
    P.v.push_back(scene.v[k]);
    P.m.push_back(scene.m[k]);
    P.V0.push_back(scene.m[k] / scene.rho[k]);
    P.lambda.push_back(lame_lambda(K, G));
    P.mu.push_back(G);
    P.E.push_back(9.0 * K * G / (3.0 * K + G));
    P.c.push_back(scene.c[k]);
    P.clamped.push_back(scene.clamped[k]);
  }
  P.resize_derived();
  find_reference_neighbours(P, par.h);
  return P;
}

void find_reference_neighbours(TLParticles& P, double h) {
  const double reach = kernel::kSupport * h, support2 = reach * reach;
  sph::CellGrid grid;
  grid.build(P.X, reach);
  const std::vector<int>& order = grid.order();  // candidates come as ranges of this order
  P.neighbours.assign(P.size(), {});
  P.L0.assign(P.size(), Mat2::Identity());
  sph::parallel_for(P.size(), sph::kTeamAtAnySize, [&](long i) {
    const Vec2 X_i = P.X[i];
    std::vector<ReferenceNeighbour>& neighbours = P.neighbours[i];
    Mat2 M = Mat2::Zero();
    grid.for_each_candidate_range(X_i, [&](int begin, int end) {
      for (int k = begin; k < end; ++k) {
        const int j = order[k];
        const Vec2 X_ij = X_i - P.X[j];
        const double r2 = X_ij.squaredNorm();
        if (r2 >= support2 || j == i) continue;
        const double r_ij = std::sqrt(r2);
        const Vec2 grad_W0 = kernel::grad_W(X_ij, r_ij, h);
        neighbours.push_back({j, kernel::W(r_ij, h), kernel::dW_dr(r_ij, h), grad_W0, grad_W0});
        M += sph::renormalisation_term(P.V0[j], grad_W0, X_ij);
      }
    });
    P.L0[i] = reference_correction(M);
    for (ReferenceNeighbour& neighbour : neighbours)
      neighbour.grad_W0_tilde = P.L0[i] * neighbour.grad_W0;
  });
  // A free particle reads, of its reference neighbours j (within 2h, fixed
  // for the run), their deformation and stress: sums over j's own
  // neighbours k of u_k, which for a clamped k is zero and needs nothing
  // computed. So a clamped particle is read only if it is some free
  // particle's neighbour, and with fixed neighbours no free particle can
  // come closer: those with none are out of reach (inert).
  P.inert.resize(P.size());
  for (std::size_t i = 0; i < P.size(); ++i)
    P.inert[i] = P.clamped[i] && std::all_of(P.neighbours[i].begin(), P.neighbours[i].end(),
                                             [&P](const ReferenceNeighbour& neighbour) {
                                               return P.clamped[neighbour.j] != 0;
                                             });
  P.reach_end = reach_end(P.inert);
}

}  // namespace cosph::solid::tl
