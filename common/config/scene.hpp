#pragma once
// The typed scene: what a scene file (YAML) describes, after validation. Plain
// aggregates in SI units (m, kg, s, Pa, J/kg); nothing of YAML leaks out. The
// defaults below are the scene file's defaults (the schema reference prints
// them from here). Load one with load_scene() (scene_loader.hpp).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/config/shapes.hpp"
#include "common/eos/any_eos.hpp"

namespace mpfd::config {

/// The Courant numbers a solver uses when the scene gives none: at least 20 %
/// below the smallest stable CFL the stability suite found for it
/// (docs/stability.md: FDM 1.0; MPM 0.275, linear shape functions with the
/// default usavg on the 2D blast, which goes unstable at 0.3).
inline constexpr double kFdmDefaultCfl = 0.5;
inline constexpr double kMpmDefaultCfl = 0.2;

struct TimeControl {
  double end = 0.0;           ///< end time [s]
  std::optional<double> cfl;  ///< Courant number of both solvers [-], in (0, 1]; absent: defaults
  int max_steps = 1000000;    ///< the run stops with an error after this many steps

  /// The Courant number of the FDM solver: cfl, or kFdmDefaultCfl.
  [[nodiscard]] double fdm_cfl() const { return cfl.value_or(kFdmDefaultCfl); }
  /// The Courant number of the MPM solver: cfl, or kMpmDefaultCfl.
  [[nodiscard]] double mpm_cfl() const { return cfl.value_or(kMpmDefaultCfl); }
};

/// spherical: one-dimensional, x is the radius from the origin (seed S; mpm_solver run).
enum class Geometry { cartesian, spherical };

struct Domain {
  Vec3 lower{};                       ///< [m]
  Vec3 upper{};                       ///< [m], > lower on every axis
  std::array<int, 3> cells{1, 1, 1};  ///< cells per axis; an unused axis has one cell
  Geometry geometry = Geometry::cartesian;
};

struct Zone {
  Vec3 lower{};  ///< [m], on a grid line
  Vec3 upper{};  ///< [m], on a grid line
};

struct MpmZone {
  Vec3 lower{};                               ///< [m], on a grid line
  Vec3 upper{};                               ///< [m], on a grid line
  std::optional<double> activation_pressure;  ///< [Pa]; dormant until exceeded; absent: always on
};

/// Where each solver works (CFDMP, T §4.2). Absent from a scene: one solver owns the domain.
struct Zones {
  std::optional<Zone> fdm;
  std::optional<MpmZone> mpm;
  int handshake_width = 5;  ///< overlap of the FDM and MPM zones [cells], T §4.2
};

struct NoStrength {};

struct ElasticStrength {
  double shear_modulus = 0.0;  ///< [Pa]
};

/// Johnson-Cook flow stress, T (2-64):
/// sigma_y = (A + B eps_p^n)(1 + C ln(epsdot/epsdot0))(1 - T*^m), T* = (T - T_room)/(T_melt -
/// T_room).
struct JohnsonCook {
  double a = 0.0;                      ///< A [Pa]
  double b = 0.0;                      ///< B [Pa]
  double n = 0.0;                      ///< [-]
  double c = 0.0;                      ///< C [-]
  double m = 0.0;                      ///< [-]
  double room_temperature = 293.0;     ///< T_room [K]
  double melt_temperature = 0.0;       ///< T_melt [K]
  double reference_strain_rate = 1.0;  ///< epsdot0 [1/s]
  double specific_heat = 0.0;          ///< [J/(kg K)], for the adiabatic temperature rise
  double shear_modulus = 0.0;          ///< [Pa]
  /// Equivalent plastic strain at failure [-]; absent: never fails.
  std::optional<double> failure_strain;
};

using AnyStrength = std::variant<NoStrength, ElasticStrength, JohnsonCook>;

struct Explosive {
  double detonation_velocity = 0.0;  ///< D [m/s], program burn T (3-1)
};

struct Material {
  std::string name;
  eos::AnyEos eos;
  AnyStrength strength;
  std::optional<Explosive> explosive;  ///< present for materials that detonate
};

/// A material's thermodynamic and kinetic state; exactly one of pressure and
/// specific_internal_energy is set.
struct MaterialState {
  std::string material;                            ///< a name in Scene::materials
  double density = 0.0;                            ///< [kg/m^3]
  Vec3 velocity{};                                 ///< [m/s]
  std::optional<double> pressure;                  ///< [Pa]
  std::optional<double> specific_internal_energy;  ///< [J/kg]
};

/// A region of the domain filled with one material; later bodies overwrite earlier ones.
struct Body {
  std::string name;
  Shape shape;
  MaterialState state;
  int particles_per_axis = 2;  ///< MPM particles per cell along each active axis
  /// MPM: a fixed particle set (a clamp): its particles keep zero velocity and
  /// position, and the grid nodes they touch are held at rest (docs/mpm.md).
  bool fixed = false;
};

enum class Burn { program, instantaneous };

/// Unreacted explosive at its reference density; its material has an `explosive` section.
struct Charge {
  std::string name;
  std::string material;
  Shape shape;
  std::optional<Vec3> detonation_point;  ///< [m]; required for program burn
  Burn burn = Burn::program;
  int particles_per_axis = 2;
};

/// non_reflecting: MPM only, Lysmer-Kuhlemeyer viscous tractions (W §2.4); open to particles.
enum class BoundaryKind { outflow, wall, symmetry, non_reflecting };
enum class Face : std::size_t { x_lower, x_upper, y_lower, y_upper, z_lower, z_upper };
/// The faces as the scene's `boundaries` keys name them, in Face order.
inline constexpr const char* kFaceNames[] = {"x_lower", "x_upper", "y_lower",
                                             "y_upper", "z_lower", "z_upper"};

struct Boundaries {
  std::array<BoundaryKind, 6> faces{};  ///< indexed by Face; default outflow everywhere

  BoundaryKind operator[](Face f) const { return faces[static_cast<std::size_t>(f)]; }
};

/// What a gauge samples: the fixed point `position` (whatever lies there now), or
/// the material point bound to it at the start of the run (the thesis's tracking
/// points, T §3.4.4): the MPM particle nearest `position` at t = 0, wherever it moves.
enum class GaugeFollow { point, material };

struct Gauge {
  std::string name;
  Vec3 position{};  ///< [m], inside the domain
  GaugeFollow follow = GaugeFollow::point;
};

/// Cell fields a snapshot may hold (docs/output.md).
enum class Field {
  density,
  velocity,
  pressure,
  specific_internal_energy,
  sound_speed,
  material,
  volume_fraction,
  burn_fraction
};

struct Output {
  double interval = 0.0;  ///< time between field snapshots [s]
  std::vector<Field> fields{Field::density, Field::velocity, Field::pressure};
  std::optional<double> gauge_interval;  ///< time between gauge samples [s]; absent: every step
};

enum class Method { fdm, mpm, cfdmp, afdmp };
enum class ShapeFunction { linear, gimp, cpgimp };
enum class MpmUpdate { musl, usl, usavg };

struct FdmOptions {
  double artificial_viscosity =
      1.0;                         ///< coefficient of the adaptive viscosity, T (2-56)-(2-58) [-]
  int viscosity_switch_power = 1;  ///< p of theta^p, the shock switch T (2-57) in (2-56) [-]
  int tracers_per_axis = 2;        ///< massless tracers per cell and active axis, T §3.2.2 [-]
};

/// Multi-velocity-field contact between the MPM bodies (T §2.1.3); absent: one
/// velocity field, i.e. no-slip contact.
struct MpmContact {
  double friction = 0.0;  ///< Coulomb µ of T (2-32) [-]
  std::optional<std::string>
      normal_body;  ///< body whose surface gives the normal; absent: stiffest
};

struct MpmOptions {
  ShapeFunction shape_function = ShapeFunction::linear;
  /// usavg: its strain update loses no energy on strong shocks (docs/stability.md).
  /// A scene file that leaves it out gets musl instead with solver.mpm.contact or
  /// geometry spherical, which have no usavg yet (parse_scene).
  MpmUpdate update = MpmUpdate::usavg;
  double bulk_viscosity_quadratic = 1.5;  ///< c0 of the artificial bulk viscosity (S) [-]
  double bulk_viscosity_linear = 0.06;    ///< c1 of the artificial bulk viscosity (S) [-]
  Vec3 gravity{};                         ///< body force per unit mass [m/s^2]
  double shear_damping = 0.0;             ///< Q_s of T (2-48) [-]; 0: no shear-mode damping
  double reference_pressure = 0.0;        ///< p_ref taken off the stress in the internal force [Pa]
  std::optional<MpmContact> contact;
};

/// Phase 1 of AFDMP: the 3D MPM (T §3.2.1) or the 1D spherical MPM (S; T §4.4.3).
enum class AfdmpStart { mpm, spherical };

/// The 1D spherical detonation stage of `start: spherical` (S), remapped onto the FDM grid.
struct AfdmpSpherical {
  std::optional<double> handoff_radius;  ///< [m]; the stage ends when the front reaches it
  double front_overpressure = 1000.0;    ///< [Pa]; front = outermost r with p - p_ambient >= this
  std::optional<double> grid_spacing;    ///< [m]; absent: the domain's smallest cell size / 4
  int particles_per_cell = 2;            ///< [-], >= 2
  ShapeFunction shape_function = ShapeFunction::gimp;  ///< linear or gimp
  double cfl = 0.2;                                    ///< [-], in (0, 1]
  /// Send each material's own start in the cells the products' surface cuts
  /// (coupler/remap/shell_material_sums.hpp); off: they start from the cell's state.
  bool material_start = false;
};

struct AfdmpOptions {
  AfdmpStart start = AfdmpStart::mpm;
  AfdmpSpherical spherical;
};

struct Solver {
  Method method = Method::fdm;
  FdmOptions fdm;
  MpmOptions mpm;
  AfdmpOptions afdmp;
};

struct Scene {
  std::string name;
  TimeControl time;
  Domain domain;
  std::optional<Zones> zones;
  std::vector<Material> materials;
  MaterialState initial;  ///< background fill of the whole domain
  std::vector<Body> bodies;
  std::vector<Charge> charges;
  Boundaries boundaries;
  std::vector<Gauge> gauges;
  Output output;
  Solver solver;
};

/// The material called `name`, or nullptr.
const Material* find_material(const Scene& scene, std::string_view name);

/// A solid: the material has a strength model.
[[nodiscard]] bool has_strength(const Material& material);
/// The scene has a solid material (a structure for the MPM).
[[nodiscard]] bool has_structure(const Scene& scene);

/// The axes as messages name them.
inline constexpr const char* kAxisNames[] = {"x", "y", "z"};

/// Ghost layers the FDM reads beyond its zone in CFDMP: its sweep reads i-3 ... i+3
/// (fdm_solver/pencil_io.hpp kGhost); the coupler fills them from the MPM's nodes.
inline constexpr int kFdmGhostLayers = 3;
/// Cells past the FDM zone whose particles reach the FDM in CFDMP: its ghost layers
/// and the next cell, whose particles share the ghost cells' outer corner nodes (the
/// coupler fills the ghost cells from nodes [e, e + 4)); structures stay beyond them.
inline constexpr int kFdmReachCells = kFdmGhostLayers + 1;

}  // namespace mpfd::config
