#include "common/config/scene_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "common/config/check_text.hpp"

namespace mpfd::config {
namespace {

void check_material(const Scene& s, const std::string& name, const std::string& path,
                    Diagnostics& d) {
  if (find_material(s, name)) return;
  std::vector<std::string> names;
  for (const Material& m : s.materials) names.push_back(m.name);
  d.error(path, "no material named '" + name + "'" + did_you_mean(name, names) +
                    " (defined: " + join(names) + ")");
}

void check_material_references(const Scene& s, Diagnostics& d) {
  if (!d.clean("materials")) return;
  if (d.clean("initial")) check_material(s, s.initial.material, "initial.material", d);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    check_material(s, s.bodies[i].state.material, item("bodies", i) + ".material", d);
  }
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    const std::string path = item("charges", i) + ".material";
    check_material(s, s.charges[i].material, path, d);
    const Material* m = find_material(s, s.charges[i].material);
    if (m && (!m->explosive || !std::holds_alternative<eos::Jwl>(m->eos))) {
      d.error(path, "material '" + m->name +
                        "' cannot detonate; expected a material with eos type jwl and an "
                        "`explosive` section");
    }
  }
}

void check_unique(const std::vector<std::pair<std::string, std::string>>& names, Diagnostics& d) {
  std::map<std::string, std::string> seen;
  for (const auto& [name, path] : names) {
    if (const auto [first, fresh] = seen.emplace(name, path); !fresh) {
      d.error(path + ".name", "duplicate name '" + name + "' (also " + first->second + ")");
    }
  }
}

void check_names(const Scene& s, Diagnostics& d) {
  std::vector<std::pair<std::string, std::string>> regions, gauges;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    regions.emplace_back(s.bodies[i].name, item("bodies", i));
  }
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    regions.emplace_back(s.charges[i].name, item("charges", i));
  }
  for (std::size_t i = 0; i < s.gauges.size(); ++i) {
    gauges.emplace_back(s.gauges[i].name, item("gauges", i));
  }
  check_unique(regions, d);
  check_unique(gauges, d);
}

void check_burn(const Scene& s, Diagnostics& d) {
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    const Charge& c = s.charges[i];
    const std::string path = item("charges", i) + ".detonation_point";
    if (c.burn == Burn::program && !c.detonation_point) {
      d.error(path, "required key is missing; expected a list of 3 numbers (burn is program)");
    } else if (c.burn == Burn::instantaneous && c.detonation_point) {
      d.error(path, "not used with burn: instantaneous; remove it");
    }
  }
}

void check_output(const Scene& s, Diagnostics& d) {
  const std::vector<Field>& fields = s.output.fields;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (std::find(fields.begin(), fields.begin() + static_cast<std::ptrdiff_t>(i), fields[i]) !=
        fields.begin() + static_cast<std::ptrdiff_t>(i)) {
      d.error(item("output.fields", i), "listed twice");
    }
  }
}

bool inside(const Domain& d, const Vec3& p) {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < d.lower[i] || p[i] > d.upper[i]) return false;
  }
  return true;
}

bool overlaps(const Domain& d, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    if (b.upper[i] <= d.lower[i] || b.lower[i] >= d.upper[i]) return false;
  }
  return true;
}

void check_inside_domain(const Scene& s, Diagnostics& d) {
  const Domain& dom = s.domain;
  for (std::size_t i = 0; i < s.gauges.size(); ++i) {
    if (!inside(dom, s.gauges[i].position)) {
      d.error(item("gauges", i) + ".position", "expected a point inside " + domain_text(dom) +
                                                   ", got " + text(s.gauges[i].position));
    }
  }
  const auto check_shape = [&](const Shape& shape, const std::string& path) {
    if (!overlaps(dom, bounding_box(shape))) {
      d.error(path + ".shape",
              "expected a shape overlapping " + domain_text(dom) + ", got one entirely outside");
    }
  };
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    check_shape(s.bodies[i].shape, item("bodies", i));
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    check_shape(s.charges[i].shape, item("charges", i));
    const auto& p = s.charges[i].detonation_point;
    if (p && !inside(dom, *p)) {
      d.error(item("charges", i) + ".detonation_point",
              "expected a point inside " + domain_text(dom) + ", got " + text(*p));
    }
  }
}

void check_zone(const Domain& dom, const Vec3& lower, const Vec3& upper, const std::string& path,
                Diagnostics& d) {
  for (int i = 0; i < 3; ++i) {
    if (lower[i] < dom.lower[i] || upper[i] > dom.upper[i]) {
      d.error(path, "expected a zone inside " + domain_text(dom) + ", got " + kAxisNames[i] +
                        " from " + num(lower[i]) + " to " + num(upper[i]));
      return;
    }
  }
  for (const auto& [key, corner] : {std::pair{"lower", lower}, std::pair{"upper", upper}}) {
    for (int i = 0; i < 3; ++i) {
      const double h = cell_size(dom, i);
      const double k = (corner[i] - dom.lower[i]) / h;
      if (std::abs(k - std::round(k)) > kGridTolerance) {
        d.error(path + "." + key,
                std::string("expected coordinates on grid lines, got ") + kAxisNames[i] + " = " +
                    num(corner[i]) + " between " + num(dom.lower[i] + std::floor(k) * h) + " and " +
                    num(dom.lower[i] + std::ceil(k) * h) + " (cell size " + num(h) + ")");
      }
    }
  }
}

void check_zones(const Scene& s, Diagnostics& d) {
  if (!d.clean("zones") || !d.clean("solver")) return;
  const Method method = s.solver.method;
  const bool both = s.zones && s.zones->fdm && s.zones->mpm;
  if (method == Method::cfdmp && !both) {
    d.error("solver.method", "cfdmp needs both zones.fdm and zones.mpm");
  } else if ((method == Method::fdm || method == Method::mpm) && s.zones) {
    d.error("zones",
            "not used by solver.method fdm or mpm (one solver owns the whole domain); "
            "remove it or choose cfdmp or afdmp");
  } else if (method == Method::afdmp && s.zones && s.zones->fdm) {
    d.error("zones.fdm", "not used by solver.method afdmp (only the mpm zone is)");
  }
  if (!s.zones || !d.clean("zones")) return;
  const Zones& z = *s.zones;
  if (z.fdm) check_zone(s.domain, z.fdm->lower, z.fdm->upper, "zones.fdm", d);
  if (z.mpm) check_zone(s.domain, z.mpm->lower, z.mpm->upper, "zones.mpm", d);
  if (!both || !d.clean("zones")) return;
  for (int i = 0; i < 3; ++i) {
    if (s.domain.cells[i] == 1) continue;
    const double width =
        std::min(z.fdm->upper[i], z.mpm->upper[i]) - std::max(z.fdm->lower[i], z.mpm->lower[i]);
    const long cells = std::lround(width / cell_size(s.domain, i));
    if (cells < z.handshake_width) {
      d.error("zones.handshake_width",
              "expected the fdm and mpm zones to overlap by at least handshake_width = " +
                  std::to_string(z.handshake_width) + " cells along " + kAxisNames[i] + ", got " +
                  std::to_string(std::max(cells, 0L)));
    }
  }
}

// The non-reflecting face and the MPM options that name bodies mean something only to MPM.
void check_mpm_only(const Scene& s, Diagnostics& d) {
  if (!d.clean("boundaries") || !d.clean("solver")) return;
  for (std::size_t i = 0; i < 6; ++i) {
    if (s.boundaries.faces[i] == BoundaryKind::non_reflecting && s.solver.method != Method::mpm) {
      d.error(std::string("boundaries.") + kFaceNames[i],
              "non_reflecting is an MPM boundary (W §2.4); expected outflow, wall or symmetry "
              "with solver.method other than mpm");
    }
  }
  // Only the MPM uses it (CFDMP: the coupler takes it off the FDM cells' (4-9) too).
  if (s.solver.mpm.reference_pressure > 0.0 && s.solver.method == Method::fdm) {
    d.error("solver.mpm.reference_pressure",
            "expected 0 with solver.method fdm (no MPM runs), got " +
                num(s.solver.mpm.reference_pressure));
  }
  // usavg's first half-strain uses the summed nodal v^n: per-body contact fields
  // are not in it.
  if (s.solver.mpm.update == MpmUpdate::usavg && s.solver.mpm.contact)
    d.error("solver.mpm.update",
            "usavg is not supported with solver.mpm.contact yet; expected musl or usl, or "
            "remove solver.mpm.contact");
  if (s.solver.mpm.contact && s.solver.mpm.contact->normal_body) {
    const std::string& name = *s.solver.mpm.contact->normal_body;
    std::vector<std::string> names;
    for (const Body& b : s.bodies) names.push_back(b.name);
    for (const Charge& c : s.charges) names.push_back(c.name);
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      d.error("solver.mpm.contact.normal_body", "no body or charge named '" + name + "'" +
                                                    did_you_mean(name, names) +
                                                    " (defined: " + join(names) + ")");
    }
  }
}

// A gauge that follows the material binds to an MPM particle at t = 0; the MPM
// must own that point in every phase (mpm_solver/followed_gauges.hpp).
void check_following_gauges(const Scene& s, Diagnostics& d) {
  if (!d.clean("solver") || !d.clean("zones")) return;
  const Method method = s.solver.method;
  for (std::size_t i = 0; i < s.gauges.size(); ++i) {
    const Gauge& g = s.gauges[i];
    if (g.follow != GaugeFollow::material) continue;
    const std::string path = item("gauges", i) + ".follow";
    if (method == Method::fdm) {
      d.error(path,
              "expected point with solver.method fdm (material follows an MPM particle; "
              "the FDM has none), got material");
    } else if (s.domain.geometry == Geometry::spherical) {
      d.error(path,
              "expected point with domain.geometry spherical (the 1D run samples fixed "
              "radii), got material");
    } else if (method == Method::cfdmp || method == Method::afdmp) {
      const bool held = s.zones && s.zones->mpm && [&] {
        for (int a = 0; a < 3; ++a)
          if (g.position[a] < s.zones->mpm->lower[a] || g.position[a] > s.zones->mpm->upper[a])
            return false;
        return true;
      }();
      if (!held) {
        d.error(path,
                "expected point for a gauge outside zones.mpm (material follows an MPM "
                "particle, and only zones.mpm keeps its particles in every phase), got "
                "material at " +
                    text(g.position));
      }
    }
  }
}

}  // namespace

void check_scene(const Scene& scene, Diagnostics& diagnostics) {
  check_material_references(scene, diagnostics);
  check_names(scene, diagnostics);
  check_burn(scene, diagnostics);
  check_output(scene, diagnostics);
  check_mpm_only(scene, diagnostics);
  if (!diagnostics.clean("domain")) return;
  check_inside_domain(scene, diagnostics);
  check_zones(scene, diagnostics);
  check_cfdmp_structures(scene, diagnostics);
  check_spherical_geometry(scene, diagnostics);
  check_afdmp(scene, diagnostics);
  check_following_gauges(scene, diagnostics);
}

}  // namespace mpfd::config
