#include "common/config/scene_schema.hpp"

#include <functional>
#include <memory>

namespace mpfd::config::schema {
namespace {

const Fixed<Number, 3> kPoint{Number("m")};
const Integer kParticlesPerAxis{Range::closed(1, 8)};

std::shared_ptr<const Table<TimeControl>> time_table() {
  auto t = make_table<TimeControl>("time", "When the run ends and how big its steps may be.");
  t->required("end", &TimeControl::end, Number("s", Range::above(0)), "end time")
      .optional("cfl", &TimeControl::cfl, Number("-", Range::open_closed(0, 1)),
                "Courant number of both solvers; absent: 0.5 for the FDM, 0.2 for the MPM "
                "(docs/stability.md)")
      .optional("max_steps", &TimeControl::max_steps, Integer(Range::at_least(1)),
                "the run stops with an error after this many steps");
  return t;
}

std::shared_ptr<const Table<Domain>> domain_table() {
  auto t =
      make_table<Domain>("domain",
                         "The box that holds everything, and its uniform grid (cell size "
                         "(upper - lower) / cells). A 1D or 2D scene has one cell on its unused "
                         "axes.");
  t->required("lower", &Domain::lower, kPoint, "lowest corner")
      .required("upper", &Domain::upper, kPoint, "highest corner")
      .required("cells", &Domain::cells, Fixed<Integer, 3>(Integer(Range::at_least(1))),
                "cells along x, y, z")
      .optional(
          "geometry", &Domain::geometry,
          Enum<Geometry>({{"cartesian", Geometry::cartesian}, {"spherical", Geometry::spherical}}),
          "spherical: one-dimensional spherical symmetry (S): x is the radius, lower = "
          "[0, 0, 0], cells [n, 1, 1]; solver.method mpm; bodies and charges are spheres "
          "centred at the origin; x_lower symmetry (the centre), x_upper outflow (free "
          "surface) or non_reflecting (transmitting); gauges record the pressure at their "
          "x; mpm_solver run advances it with the 1D spherical MPM")
      .rule("upper > lower on every axis",
            [](const Domain& d, const Cursor& c) { check_box(d.lower, d.upper, c); });
  return t;
}

std::shared_ptr<const Table<Zones>> zones_table() {
  auto fdm = make_table<Zone>("zones.fdm", "The FDM (Euler) zone.");
  fdm->required("lower", &Zone::lower, kPoint, "lowest corner, on a grid line")
      .required("upper", &Zone::upper, kPoint, "highest corner, on a grid line")
      .rule("upper > lower on every axis",
            [](const Zone& z, const Cursor& c) { check_box(z.lower, z.upper, c); });
  auto mpm = make_table<MpmZone>("zones.mpm", "The MPM (fluid-structure interaction) zone.");
  mpm->required("lower", &MpmZone::lower, kPoint, "lowest corner, on a grid line")
      .required("upper", &MpmZone::upper, kPoint, "highest corner, on a grid line")
      .optional("activation_pressure", &MpmZone::activation_pressure,
                Number("Pa", Range::at_least(0)),
                "the FSI zone stays dormant (no MPM work, no requests) until the absolute "
                "pressure of an FDM cell next to its coupling face (the strip cells, T §4.3) "
                "exceeds this; at or below the ambient pressure there it wakes at t = 0; "
                "absent: active from the start (docs/coupler.md)")
      .rule("upper > lower on every axis",
            [](const MpmZone& z, const Cursor& c) { check_box(z.lower, z.upper, c); });
  auto t =
      make_table<Zones>("zones",
                        "Where each solver works when they are coupled in space (CFDMP, T §4.2). "
                        "Used only by solver.method cfdmp (both zones required; every body "
                        "with a strength model in the mpm zone beyond the fdm zone, its 3 "
                        "ghost layers and one cell more, whose particles reach the ghost cells' "
                        "nodes) and afdmp (mpm zone only: the FSI zone, a slab across the "
                        "domain with one face inside it, activation_pressure required, holding "
                        "every body with a strength model and no charge).");
  t->optional("fdm", &Zones::fdm, Nested<Zone>(fdm), "the FDM zone")
      .optional("mpm", &Zones::mpm, Nested<MpmZone>(mpm), "the MPM zone")
      .optional("handshake_width", &Zones::handshake_width, Integer(Range::at_least(1)),
                "overlap of the two zones [cells] on every active axis")
      .rule("at least one of fdm and mpm", [](const Zones& z, const Cursor& c) {
        if (!z.fdm && !z.mpm) c.error("expected at least one of the keys fdm and mpm");
      });
  return t;
}

// The keys of a material state, shared by `initial` and `bodies`; `state`
// maps the table's struct to its MaterialState.
template <class T, class Get>
void add_state_keys(Table<T>& t, Get state) {
  auto member = [state](auto field) {
    return [ state, field ](T & x) -> auto& {
      return std::invoke(field, std::invoke(state, x));
    };
  };
  t.required("material", member(&MaterialState::material), Name{}, "a key of `materials`")
      .required("density", member(&MaterialState::density), Number("kg/m^3", Range::above(0)),
                "density")
      .optional("velocity", member(&MaterialState::velocity), Fixed<Number, 3>(Number("m/s")),
                "velocity")
      .optional("pressure", member(&MaterialState::pressure), Number("Pa", Range::at_least(0)),
                "pressure; give this or specific_internal_energy")
      .optional("specific_internal_energy", member(&MaterialState::specific_internal_energy),
                Number("J/kg", Range::at_least(0)),
                "specific internal energy; give this or pressure")
      .rule("exactly one of pressure and specific_internal_energy",
            [state](const T& x, const Cursor& c) {
              const MaterialState& s = std::invoke(state, x);
              if (s.pressure.has_value() == s.specific_internal_energy.has_value()) {
                c.error("expected exactly one of the keys pressure and specific_internal_energy");
              }
            });
}

std::shared_ptr<const Table<MaterialState>> initial_table() {
  auto t =
      make_table<MaterialState>("initial", "The background state that fills the whole domain.");
  add_state_keys(
      *t, [](auto& s) -> auto& { return s; });
  return t;
}

std::shared_ptr<const Table<Body>> body_table() {
  auto t = make_table<Body>("bodies[]",
                            "A region filled with one material, over the background and the bodies "
                            "before it.");
  t->required("name", &Body::name, Name{}, "unique among bodies and charges")
      .required("shape", &Body::shape, ShapeType{}, "the region");
  add_state_keys(
      *t, [](auto& b) -> auto& { return b.state; });
  t->optional("particles_per_axis", &Body::particles_per_axis, kParticlesPerAxis,
              "MPM particles per cell along each active axis (2 gives 2, 4 and 8 particles per "
              "cell in 1D, 2D and 3D)")
      .optional("fixed", &Body::fixed, Boolean{},
                "MPM: a fixed particle set (e.g. a clamp at a plate's edge): its particles keep "
                "zero velocity and the grid nodes they touch are held at rest; with "
                "solver.mpm.contact only its own velocity field is");
  return t;
}

std::shared_ptr<const Table<Charge>> charge_table() {
  auto t = make_table<Charge>(
      "charges[]", "Unreacted explosive at its material's rho0, filled over the bodies.");
  t->required("name", &Charge::name, Name{}, "unique among bodies and charges")
      .required("material", &Charge::material, Name{}, "a material with an `explosive` section")
      .required("shape", &Charge::shape, ShapeType{}, "the region")
      .optional("detonation_point", &Charge::detonation_point, kPoint,
                "where the program burn starts; required for burn: program, not allowed "
                "otherwise")
      .optional("burn", &Charge::burn,
                Enum<Burn>({{"program", Burn::program}, {"instantaneous", Burn::instantaneous}}),
                "program: ignition at distance / D from the detonation point, T (3-1), (3-2); "
                "instantaneous: all at t = 0")
      .optional("particles_per_axis", &Charge::particles_per_axis, kParticlesPerAxis,
                "MPM particles per cell along each active axis");
  return t;
}

std::shared_ptr<const Table<Boundaries>> boundaries_table() {
  auto t =
      make_table<Boundaries>("boundaries",
                             "The condition on each face of the domain. outflow: zero-gradient, "
                             "open; wall: rigid, reflecting; symmetry: mirror plane; "
                             "non_reflecting (solver.method mpm only): open, with the viscous "
                             "tractions -rho c_p v_n and -rho c_s v_t of W §2.4 and the pressure "
                             "of `initial` as the far field.");
  const Enum<BoundaryKind> kind({{"outflow", BoundaryKind::outflow},
                                 {"wall", BoundaryKind::wall},
                                 {"symmetry", BoundaryKind::symmetry},
                                 {"non_reflecting", BoundaryKind::non_reflecting}});
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < 6; ++i) {
    const std::string axis = axes[i / 2];
    const std::string side = i % 2 == 0 ? "lower" : "upper";
    t->optional(
        axis + "_" + side, [i](Boundaries& b) -> BoundaryKind& { return b.faces[i]; }, kind,
        "the face at " + axis + " = domain." + side + "[" + std::to_string(i / 2) + "]");
  }
  return t;
}

std::shared_ptr<const Table<Gauge>> gauge_table() {
  auto t = make_table<Gauge>("gauges[]", "A named point whose history is recorded.");
  t->required("name", &Gauge::name, Name{}, "unique among gauges")
      .required("position", &Gauge::position, kPoint, "inside the domain")
      .optional(
          "follow", &Gauge::follow,
          Enum<GaugeFollow>({{"point", GaugeFollow::point}, {"material", GaugeFollow::material}}),
          "point: the history at the fixed position (the cell or particle there now); "
          "material: the MPM particle nearest the position at t = 0 (lowest id on a tie; "
          "none within one cell is an error), followed wherever it moves (its density, "
          "pressure, velocity, position and, with a structure, Mises stress; NaN once "
          "it has left the domain). material needs particles there: solver.method mpm, "
          "or a point in zones.mpm with cfdmp or afdmp");
  return t;
}

std::shared_ptr<const Table<Output>> output_table() {
  auto t = make_table<Output>("output", "What is written and how often.");
  const Enum<Field> field({{"density", Field::density},
                           {"velocity", Field::velocity},
                           {"pressure", Field::pressure},
                           {"specific_internal_energy", Field::specific_internal_energy},
                           {"sound_speed", Field::sound_speed},
                           {"material", Field::material},
                           {"volume_fraction", Field::volume_fraction},
                           {"burn_fraction", Field::burn_fraction}});
  t->required("interval", &Output::interval, Number("s", Range::above(0)),
              "time between field snapshots")
      .optional("fields", &Output::fields, ListOf<Enum<Field>>(field, 1),
                "cell fields in each snapshot, each named once (docs/output.md)")
      .optional("gauge_interval", &Output::gauge_interval, Number("s", Range::above(0)),
                "time between gauge samples; absent: every step");
  return t;
}

std::shared_ptr<const Table<Solver>> solver_table() {
  auto fdm = make_table<FdmOptions>("solver.fdm", "Options of the Euler solver (T §2.2).");
  fdm->optional("artificial_viscosity", &FdmOptions::artificial_viscosity,
                Number("-", Range::at_least(0)),
                "coefficient of the adaptive artificial viscosity, T (2-56)-(2-58)");
  fdm->optional("viscosity_switch_power", &FdmOptions::viscosity_switch_power,
                Integer(Range::closed(1, 4)),
                "power p of the shock switch theta of T (2-57) in the viscosity of (2-56); 1 is "
                "the thesis, 2 keeps the viscosity at jumps and lowers it where the density "
                "bends gently (docs/fdm.md)");
  fdm->optional("tracers_per_axis", &FdmOptions::tracers_per_axis, Integer(Range::closed(1, 8)),
                "massless tracers per cell along each active axis, seeded when the scene has "
                "more than one material in the FDM zone, T §3.2.2");
  auto contact = make_table<MpmContact>(
      "solver.mpm.contact",
      "Bardenhagen's contact, T §2.1.3: every body and charge gets its own velocity field where "
      "two or more meet; they may slide (Coulomb friction) and separate, not interpenetrate.");
  contact
      ->optional("friction", &MpmContact::friction, Number("-", Range::at_least(0)),
                 "Coulomb coefficient µ, T (2-32)")
      .optional("normal_body", &MpmContact::normal_body, Name{},
                "the body or charge whose surface gives the common normal, T (2-24); absent: "
                "fixed bodies first, then the largest rho c^2 at the start, then the first "
                "listed");
  auto mpm = make_table<MpmOptions>("solver.mpm", "Options of the MPM solver (T §2.1).");
  mpm->optional(
         "shape_function", &MpmOptions::shape_function,
         Enum<ShapeFunction>({{"linear", ShapeFunction::linear},
                              {"gimp", ShapeFunction::gimp},
                              {"cpgimp", ShapeFunction::cpgimp}}),
         "linear: trilinear, T (2-7); gimp: uGIMP, W §2.3 (particle domains of constant size); "
         "cpgimp: W §2.3's cpGIMP (domains stretched by the diagonal of the deformation "
         "gradient)")
      .optional(
          "update", &MpmOptions::update,
          Enum<MpmUpdate>(
              {{"musl", MpmUpdate::musl}, {"usl", MpmUpdate::usl}, {"usavg", MpmUpdate::usavg}}),
          "musl re-maps particle velocities to the nodes before the strain update, T "
          "(2-17); usl strains with the nodal v^{n+1}; usavg (Nairn 2003, CMES 4(6); "
          "Wallstedt & Guilkey 2008) strains half with the nodal v^n before the forces "
          "and half with the re-mapped v^{n+1} after, so that the pressure work matches "
          "the kinetic energy gained (strong shocks into cold gas, docs/stability.md), "
          "at ~1.5x musl's cost per step. Left out: usavg, but musl with solver.mpm.contact "
          "or geometry spherical, which have no usavg yet")
      .optional("bulk_viscosity_quadratic", &MpmOptions::bulk_viscosity_quadratic,
                Number("-", Range::at_least(0)),
                "c0 of the artificial bulk viscosity q = rho l (c0 l d^2 - c1 c d) in compression "
                "(S; l the smallest cell size, d the volumetric strain rate); 0 with the linear "
                "term 0 turns it off")
      .optional("bulk_viscosity_linear", &MpmOptions::bulk_viscosity_linear,
                Number("-", Range::at_least(0)), "c1 of the artificial bulk viscosity (S)")
      .optional("gravity", &MpmOptions::gravity, Fixed<Number, 3>(Number("m/s^2")),
                "body force per unit mass on every particle")
      .optional("shear_damping", &MpmOptions::shear_damping, Number("-", Range::at_least(0)),
                "Q_s of the shear-mode damping, T (2-33)-(2-48); 0 turns it off (the thesis "
                "gives no value; with reference_pressure or GIMP, 0.1 keeps still air at rest, "
                "docs/mpm.md)")
      .optional("reference_pressure", &MpmOptions::reference_pressure,
                Number("Pa", Range::at_least(0)),
                "p_ref: the internal force is computed from sigma + p_ref I, as if every empty "
                "region and every face were held at p_ref (an outflow face then has gas at "
                "p_ref beyond it; a non_reflecting face's far field pushes with its pressure "
                "less p_ref). Valid where the bodies are surrounded by gas at p_ref, e.g. the "
                "ambient pressure of air that fills the domain; not with a free surface to "
                "vacuum. Removes the growth of still 2D air (docs/mpm.md). 0: off; mpm and afdmp "
                "only (the coupler's CFDMP node loads carry the full pressure)")
      .optional("contact", &MpmOptions::contact, Nested<MpmContact>(contact),
                "multi-velocity-field contact between the bodies; absent: one velocity field "
                "(no-slip)");
  auto spherical = make_table<AfdmpSpherical>(
      "solver.afdmp.spherical",
      "The 1D spherical detonation stage of start: spherical (S): the charge detonates in the "
      "1D spherical MPM until its shock front reaches handoff_radius, then its radial profiles "
      "are remapped onto the FDM grid.");
  spherical
      ->optional("handoff_radius", &AfdmpSpherical::handoff_radius, Number("m", Range::above(0)),
                 "the stage ends when the front reaches this radius (S: before the wave reaches "
                 "an interface or a structure); required with start: spherical")
      .optional("front_overpressure", &AfdmpSpherical::front_overpressure,
                Number("Pa", Range::above(0)),
                "the front is the outermost radius where p - p_ambient >= this")
      .optional("grid_spacing", &AfdmpSpherical::grid_spacing, Number("m", Range::above(0)),
                "h of the 1D grid; the charge radius must be a multiple of it; absent: the "
                "domain's smallest cell size / 4")
      .optional("particles_per_cell", &AfdmpSpherical::particles_per_cell,
                Integer(Range::at_least(2)), "particles per 1D cell")
      .optional(
          "shape_function", &AfdmpSpherical::shape_function,
          Enum<ShapeFunction>({{"linear", ShapeFunction::linear}, {"gimp", ShapeFunction::gimp}}),
          "shape functions of the 1D grid (linear peaks do not converge, "
          "mpm_solver/spherical/README.md)")
      .optional("cfl", &AfdmpSpherical::cfl, Number("-", Range::open_closed(0, 1)),
                "Courant number of the 1D stage (strong blasts need <= 0.2, "
                "mpm_solver/spherical/README.md)")
      .optional("material_start", &AfdmpSpherical::material_start, Boolean{},
                "at the remap, each material of a cell the products' surface cuts starts from "
                "its own shells' state, not the cell's (needs solver.fdm.tracers_per_axis > 1; "
                "costs ~100 B per cell at the handoff's memory peak, docs/afdmp.md)");
  auto afdmp = make_table<AfdmpOptions>("solver.afdmp", "Options of AFDMP (T §3.2).");
  afdmp
      ->optional("start", &AfdmpOptions::start,
                 Enum<AfdmpStart>({{"mpm", AfdmpStart::mpm}, {"spherical", AfdmpStart::spherical}}),
                 "phase 1 (the detonation) by the MPM on the scene's grid (T §3.2.1) or by the "
                 "1D spherical MPM remapped onto the FDM grid (S; T §4.4.3)")
      .optional("spherical", &AfdmpOptions::spherical, Nested<AfdmpSpherical>(spherical),
                "the 1D stage of start: spherical");
  auto t = make_table<Solver>("solver", "Which method runs the scene, and its options.");
  t->optional("method", &Solver::method,
              Enum<Method>({{"fdm", Method::fdm},
                            {"mpm", Method::mpm},
                            {"cfdmp", Method::cfdmp},
                            {"afdmp", Method::afdmp}}),
              "fdm or mpm: one solver on the whole domain; cfdmp: coupled in space by `zones`; "
              "afdmp: alternating in time, T §3.2")
      .optional("fdm", &Solver::fdm, Nested<FdmOptions>(fdm), "FDM options")
      .optional("mpm", &Solver::mpm, Nested<MpmOptions>(mpm), "MPM options")
      .optional("afdmp", &Solver::afdmp, Nested<AfdmpOptions>(afdmp), "AFDMP options");
  return t;
}

std::shared_ptr<const Table<Scene>> build_scene_table() {
  auto t = make_table<Scene>("scene", "The top level of a scene file.");
  t->required("name", &Scene::name, Name{}, "names the run's output files")
      .required("time", &Scene::time, Nested<TimeControl>(time_table()), "time control")
      .required("domain", &Scene::domain, Nested<Domain>(domain_table()), "domain and grid")
      .optional("zones", &Scene::zones, Nested<Zones>(zones_table()), "solver zones")
      .required("materials", &Scene::materials,
                NamedMap<Material>(material_table(), &Material::name), "materials by name")
      .required("initial", &Scene::initial, Nested<MaterialState>(initial_table()),
                "background state")
      .optional("bodies", &Scene::bodies, ListOf<Nested<Body>>(Nested<Body>(body_table())),
                "material regions, filled in order")
      .optional("charges", &Scene::charges, ListOf<Nested<Charge>>(Nested<Charge>(charge_table())),
                "explosive charges")
      .optional("boundaries", &Scene::boundaries, Nested<Boundaries>(boundaries_table()),
                "boundary condition per face")
      .optional("gauges", &Scene::gauges, ListOf<Nested<Gauge>>(Nested<Gauge>(gauge_table())),
                "recorded points")
      .required("output", &Scene::output, Nested<Output>(output_table()), "output control")
      .optional("solver", &Scene::solver, Nested<Solver>(solver_table()), "method and options");
  return t;
}

}  // namespace

const Table<Scene>& scene_table() {
  static const std::shared_ptr<const Table<Scene>> built = build_scene_table();
  return *built;
}

}  // namespace mpfd::config::schema
