#include "mpm_solver/serve/write_output.hpp"

#include "cosim/serving/protocol_error.hpp"

namespace mpfd::mpm {

cosim::v1::OutputWritten write_output(ServedZone& zone, const cosim::v1::WriteOutput& request) {
  if (zone.output_dir.empty())
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO, "WriteOutput: Setup gave no output_dir");
  if (!request.directory().empty() && std::filesystem::path(request.directory()) != zone.output_dir)
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_IO,
                               "WriteOutput directory '" + request.directory() +
                                   "' differs from Setup's output_dir '" +
                                   zone.output_dir.string() + "'; mpm_solver writes one");
  cosim::v1::OutputWritten written;
  try {
    if (!zone.snapshots) {
      std::filesystem::create_directories(zone.output_dir);
      zone.snapshots.emplace(zone.output_dir, zone.solver.grid());
    }
    written.add_files(
        zone.snapshots
            ->write(zone.solver.steps(), zone.time(), {}, zone.snapshot_fields.views(zone.solver))
            .string());
  } catch (const std::exception& error) {
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_IO,
        "WriteOutput into '" + zone.output_dir.string() + "' failed: " + error.what());
  }
  written.add_files((zone.output_dir / "particles.xmf").string());
  return written;
}

void resume_snapshots(ServedZone& zone, const std::string& history) {
  if (zone.output_dir.empty() || (io::SnapshotWriter::empty_history(history) && !zone.snapshots))
    return;
  if (!zone.snapshots) {
    std::filesystem::create_directories(zone.output_dir);
    zone.snapshots.emplace(zone.output_dir, zone.solver.grid());
  }
  zone.snapshots->resume(history);
}

}  // namespace mpfd::mpm
