// The Jaumann solid's particles, struct-of-arrays. Clamped particles are part
// of the body: they carry stress and act on their neighbours, but do not move.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "rate_sums.hpp"
#include "solid_scene.hpp"
#include "sphcore/ordered_shares.hpp"
#include "sphcore/types.hpp"

namespace cosph::solid::jaumann {

using sph::Mat2;
using sph::Vec2;

// A neighbour j > i of particle i, as found by the rates pass and reused by the
// momentum pass: each pair is listed once, by its lower index.
struct Neighbour {
  int j;
  double W_ij;
  Vec2 grad_W_ij;
};

struct JaumannParticles {
  // State, carried from step to step (permuted with the neighbour grid).
  std::vector<int> id;
  std::vector<Vec2> x, v;
  std::vector<Vec2> x0;  // initial position (displacements, gauges)
  std::vector<double> rho, m;
  std::vector<Mat2> s;          // deviatoric stress
  std::vector<double> K, G, c;  // material: bulk and shear moduli, P-wave speed
  std::vector<double> sigma_y;  // material: von Mises yield stress (used when fracture is on)
  std::vector<std::uint8_t> clamped, failed;
  // Clamped and out of reach of every particle that can move: its velocity
  // gradient, hence its rates, are zero for good, so the passes skip it.
  std::vector<std::uint8_t> inert;
  // Clamped, and nothing a free particle reads depends on it
  // (clamp_reach.hpp): inert too, and no particle's neighbour candidate.
  std::vector<std::uint8_t> out_of_reach;
  // Acceleration imposed from outside (the coupler's fluid forces); zero alone.
  std::vector<Vec2> external_a;
  // The total acceleration of the last closing kick (own, gravity and the
  // coupler's; zero for clamped): the moving wall's a_w sent to the coupler.
  std::vector<Vec2> kick_a;

  // The passes visit the particles before this one (clamp_reach.hpp): one
  // past the last in reach, set at each sort.
  std::size_t reach_end = static_cast<std::size_t>(-1);

  // Derived each step from the state.
  std::vector<double> p;                           // pressure P = K (rho/rho0 - 1)
  std::vector<Mat2> sigma;                         // stress -P I + s (failed: compression only)
  std::vector<Mat2> R;                             // artificial stress (zero when off)
  std::vector<Mat2> L;                             // kernel-gradient renormalisation matrix
  std::vector<Mat2> sigma_L;                       // sigma L, the renormalised momentum flux
  std::vector<Vec2> a;                             // dv/dt
  std::vector<double> drho;                        // drho/dt
  std::vector<double> volume;                      // m / rho, of this step's density
  std::vector<double> inverse_rho;                 // 1 / rho, of this step's density
  std::vector<Mat2> ds;                            // ds/dt
  std::vector<std::vector<Neighbour>> neighbours;  // of this step's positions
  std::vector<RateSums> rate_sums;                 // of the rates pass
  std::vector<std::optional<Mat2>> fitted_grad_v;  // solid.velocity_gradient "quadratic"
  // The pair passes' spill buffers. Blocks of 128, not the water's 1024: the
  // solids' scenes hold a few thousand particles, and two threads need several
  // blocks each to share the work (smaller blocks cost more to merge than they gain).
  sph::OrderedShares<RateSums> rate_shares{RateSums{}, 128};
  sph::OrderedShares<Vec2> a_shares{Vec2::Zero(), 128};

  std::size_t size() const { return x.size(); }

  void add(int particle_id, const Vec2& position, double density, double mass, double bulk,
           double shear, double sound_speed, bool is_clamped, double yield_stress = 0.0) {
    id.push_back(particle_id);
    x.push_back(position);
    x0.push_back(position);
    v.push_back(Vec2::Zero());
    rho.push_back(density);
    m.push_back(mass);
    s.push_back(Mat2::Zero());
    K.push_back(bulk);
    G.push_back(shear);
    c.push_back(sound_speed);
    sigma_y.push_back(yield_stress);
    clamped.push_back(is_clamped ? 1 : 0);
    failed.push_back(0);
    inert.push_back(0);
    out_of_reach.push_back(0);
    external_a.push_back(Vec2::Zero());
    kick_a.push_back(Vec2::Zero());
  }

  // The scene's particles at rest in their reference state, derived fields sized.
  static JaumannParticles from_scene(const SolidScene& scene) {
    JaumannParticles particles;
    for (std::size_t k = 0; k < scene.size(); ++k) {
      particles.add(scene.id[k], scene.x[k], scene.rho[k], scene.m[k], scene.K[k], scene.G[k],
                    scene.c[k], scene.clamped[k] != 0, scene.sigma_y[k]);
      particles.v.back() = scene.v[k];
    }
    particles.resize_derived();
    return particles;
  }

  // Sizes the derived fields to match the state.
  void resize_derived() {
    const std::size_t n = size();
    p.assign(n, 0.0);
    sigma.assign(n, Mat2::Zero());
    R.assign(n, Mat2::Zero());
    L.assign(n, Mat2::Identity());
    sigma_L.assign(n, Mat2::Zero());
    a.assign(n, Vec2::Zero());
    drho.assign(n, 0.0);
    volume.assign(n, 0.0);
    ds.assign(n, Mat2::Zero());
    neighbours.resize(n);
  }
};

}  // namespace cosph::solid::jaumann
