#pragma once
// Measures of an MPM shock tube read from the solver itself (the probe
// bench/stability/riemann_probe.cpp and the usavg tests): the particles'
// density error against the exact solution and the audited energy.

#include <string_view>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/stability/stability_scenes.hpp"

namespace mpfd::stability {

/// The problem of hard_riemann_problems() called `name`; throws mpfd::Error naming it.
[[nodiscard]] RiemannProblem hard_riemann_problem(std::string_view name);

/// Kinetic + internal energy held, plus what left through the open faces [J].
[[nodiscard]] double audited_energy(const mpm::MpmSolver& mpm);

/// The volume-weighted mean |rho_p - rho_exact(x_p)| over the particles in
/// [0, 1] m at the problem's end, over the larger initial density (diaphragm
/// at 0.5 m, as tube_scene()).
[[nodiscard]] double particle_l1_density(const mpm::ParticleSet& particles,
                                         const RiemannProblem& problem);

}  // namespace mpfd::stability
