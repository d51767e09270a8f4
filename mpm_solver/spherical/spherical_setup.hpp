#pragma once
// What a one-dimensional spherically symmetric MPM run (seed S) is built from:
// concentric layers of material around r = 0 and the numerical options.

#include <vector>

#include "common/config/scene.hpp"

namespace mpfd::mpm::spherical {

/// One shell of material from the previous layer's outer radius (0 for the first) to outer_radius.
struct RadialLayer {
  config::Material material;  ///< EOS and strength; an explosive needs material.explosive
  double outer_radius = 0.0;  ///< [m], on a grid line (a multiple of the grid spacing)
  double density = 0.0;       ///< initial density [kg/m^3]
  double specific_internal_energy = 0.0;  ///< initial e [J/kg]; TNT: E0 / rho0
  bool explosive = false;                 ///< program burn from r = 0, T (3-1), (3-2)
};

/// The surface of the outermost layer.
enum class OuterBoundary {
  free,          ///< traction free
  transmitting,  ///< traction -(p_ambient + rho c v): holds the initial outer pressure and
                 ///< absorbs a normally incident outgoing wave
};

/// Linear + quadratic artificial bulk viscosity, S eq. (16) (rebuilt, README).
struct BulkViscosity {
  double quadratic = 1.5;  ///< c0 [-] (LS-DYNA default Q1)
  double linear = 0.06;    ///< c1 [-] (LS-DYNA default Q2)
};

/// Shape functions of the radial grid (radial_shape.hpp).
enum class RadialShape {
  linear,  ///< standard MPM as seed S and T (2-7); cell-crossing noise (README)
  gimp,    ///< GIMP shells of half-width h / (2 particles_per_cell), exact moments
};

struct SphericalOptions {
  double grid_spacing = 0.0;   ///< h [m]; also l_e of S eq. (16)
  int particles_per_cell = 2;  ///< >= 2: Gauss-Legendre points of each cell (README)
  double cfl = 0.5;            ///< Courant number of stable_dt() [-], in (0, 1]
  RadialShape shape = RadialShape::gimp;
  BulkViscosity viscosity;
  OuterBoundary outer_boundary = OuterBoundary::transmitting;
  int margin_cells = 8;  ///< empty grid cells beyond the outer layer, room to expand into
};

}  // namespace mpfd::mpm::spherical
