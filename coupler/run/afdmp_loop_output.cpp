// AfdmpLoop's outputs (afdmp_loop.hpp): each output is written by the solver that
// holds the state (the 1D stage's as a CSV profile), and summary.json follows the run.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "common/core/error.hpp"
#include "common/io/output_directory.hpp"
#include "coupler/run/afdmp_loop.hpp"
#include "coupler/run/session.hpp"

namespace mpfd::coupler {

void AfdmpLoop::record_summary(const std::string& status, double wall) {
  gauges_.flush();
  summary_.set_detail("gauges", gauges_.listing());
  summary_.set_status(status);
  summary_.set_progress(report_.steps, report_.time, scene_.time.end, wall);
  const auto entries = audit_.entries();
  summary_.set_conservation(entries);
  report_.mass_error = entries[0].relative_error(0);
  report_.energy_error = entries[4].relative_error(0);
  nlohmann::json phases = phases_;
  phases.push_back({{"phase", phase_name(machine_.phase())},
                    {"start", phase_time_},
                    {"steps", phase_steps_},
                    {"wall_s", seconds_since(phase_start_)}});
  summary_.set_detail("afdmp", {{"start", start_ == AfdmpStart::mpm ? "mpm" : "spherical"},
                                {"phases", phases},
                                {"transitions", transitions_},
                                {"handoffs", handoffs_},
                                {"audit", audit_.summary()},
                                {"outputs", outputs_}});
  summary_.set_detail("checkpoints", checkpoints_.summary());
  summary_.set_detail("protocol", {{"fdm_outflow", outflow_.fdm},
                                   {"mpm_outflow", outflow_.mpm},
                                   {"fdm_material_import", settings_.material_import}});
  summary_.write(options_.out_dir / "summary.json");
}

/// Output of the solver that holds the state now (the last phase's, once done),
/// and the run-long audit's reading of it.
void AfdmpLoop::write_output(int index) {
  audit_holder(holder_);
  if (holder_ == "spherical")
    write_stage_profile(index);
  else
    write_solver_output(holder_, index);
}

void AfdmpLoop::write_solver_output(const std::string& peer, int index) {
  cosim::Message message;
  message.header.mutable_write_output()->set_basename(peer + "_" + std::to_string(index));
  hub_.send(peer, std::move(message));
  const cosim::Message reply = hub_.receive_from(peer);
  contact_[peer] = Clock::now();
  // Each solver numbers its own snapshots: list the files that hold this output.
  nlohmann::json files = nlohmann::json::array();
  for (const auto& file : reply.header.output_written().files())
    files.push_back(io::path_in_run(file, options_.out_dir));
  outputs_.push_back(
      {{"index", index}, {"solver", peer}, {"time", report_.time}, {"files", files}});
}

/// The 1D stage's particles as CSV (radius, density, velocity, specific energy, material).
void AfdmpLoop::write_stage_profile(int index) {
  std::ostringstream name;
  name << "profile_" << std::setw(4) << std::setfill('0') << index << ".csv";
  const auto dir = options_.out_dir / "spherical";
  std::filesystem::create_directories(dir);
  std::ofstream out(dir / name.str());
  if (!out)
    throw Error("cannot write the 1D stage's profile '" + (dir / name.str()).string() + "'");
  out << "# 1D spherical stage at t = " << stage_->time() << " s\n"
      << "r_inner_m,r_outer_m,density_kg_m3,velocity_m_s,specific_internal_energy_J_kg,"
         "material\n";
  out << std::setprecision(10);
  const auto shells = stage_->shells();
  for (std::size_t k = 0; k < shells.density.size(); ++k)
    out << shells.edges[k] << ',' << shells.edges[k + 1] << ',' << shells.density[k] << ','
        << shells.velocity[k] << ',' << shells.internal_energy[k] << ',' << shells.material[k]
        << '\n';
  if (!out.flush())
    throw Error("writing the 1D stage's profile '" + (dir / name.str()).string() + "' failed");
  outputs_.push_back({{"index", index},
                      {"solver", "spherical"},
                      {"time", report_.time},
                      {"files", {io::path_in_run((dir / name.str()).string(), options_.out_dir)}}});
}

}  // namespace mpfd::coupler
