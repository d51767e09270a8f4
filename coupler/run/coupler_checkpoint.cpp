#include "coupler/run/coupler_checkpoint.hpp"

#include <cstdio>
#include <regex>

#include "common/core/error.hpp"
#include "cosim/serving/sha256.hpp"

namespace mpfd::coupler {
namespace {

namespace fs = std::filesystem;

void write_solver(io::Hdf5File& file, const std::string& name,
                  const std::optional<SolverCheckpoint>& solver) {
  file.write_attribute("/", name + "_path", solver ? solver->path : std::string());
  file.write_attribute("/", name + "_step",
                       static_cast<std::int64_t>(solver ? solver->step : std::uint64_t{0}));
}

std::optional<SolverCheckpoint> read_solver(const io::Hdf5File& file, const std::string& name) {
  const std::string path = file.read_string_attribute("/", name + "_path");
  if (path.empty()) return std::nullopt;
  return SolverCheckpoint{path,
                          static_cast<std::uint64_t>(file.read_attribute("/", name + "_step"))};
}

}  // namespace

fs::path coupler_checkpoint_file(const fs::path& out_dir, std::int64_t step) {
  char name[40];
  std::snprintf(name, sizeof name, "coupler_%06lld.h5", static_cast<long long>(step));
  return out_dir / "checkpoints" / name;
}

void write_checkpoint_header(io::Hdf5File& file, const CouplerCheckpoint& checkpoint,
                             const std::string& scene_text, int dimension) {
  file.write_attribute("/", "format", std::string(kCouplerCheckpointFormat));
  file.write_attribute("/", "format_version", kCouplerCheckpointVersion);
  file.write_attribute("/", "scene_sha256", cosim::sha256_hex(scene_text));
  file.write_attribute("/", "dimension", std::int64_t{dimension});
  file.write_attribute("/", "step", checkpoint.step);
  file.write_attribute("/", "time", checkpoint.time);
  file.write_attribute("/", "outputs", std::int64_t{checkpoint.outputs});
  write_solver(file, "fdm", checkpoint.fdm);
  write_solver(file, "mpm", checkpoint.mpm);
}

CouplerCheckpoint newest_checkpoint(const fs::path& out_dir, const std::string& scene_text,
                                    int dimension) {
  const fs::path folder = out_dir / "checkpoints";
  const std::regex pattern(R"(coupler_(\d+)\.h5)");
  std::optional<fs::path> newest;
  long long newest_step = -1;
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder)) {
      std::smatch match;
      const std::string name = entry.path().filename().string();
      if (!std::regex_match(name, match, pattern)) continue;
      const long long step = std::stoll(match[1].str());
      if (step > newest_step) {
        newest_step = step;
        newest = entry.path();
      }
    }
  if (!newest)
    throw Error("--restart: '" + folder.string() +
                "' holds no coupler_NNNNNN.h5; run with --checkpoint-every K to write them");
  const io::Hdf5File file(*newest, io::Hdf5File::Mode::read);
  const auto refuse = [&](const std::string& what) {
    throw Error("--restart: '" + newest->string() + "' " + what);
  };
  std::string format;
  try {
    format = file.read_string_attribute("/", "format");
  } catch (const std::exception&) {
    refuse("has no 'format' attribute; expected '" + std::string(kCouplerCheckpointFormat) + "'");
  }
  if (format != kCouplerCheckpointFormat)
    refuse("has format '" + format + "'; expected '" + kCouplerCheckpointFormat + "'");
  const double version = file.read_attribute("/", "format_version");
  if (version != static_cast<double>(kCouplerCheckpointVersion))
    refuse("has format_version " + std::to_string(version) + "; this coupler reads " +
           std::to_string(kCouplerCheckpointVersion));
  if (file.read_string_attribute("/", "scene_sha256") != cosim::sha256_hex(scene_text))
    refuse(
        "was written for another scene text (attribute scene_sha256); restart with the scene "
        "file of that run, unchanged");
  const auto file_dimension = static_cast<int>(file.read_attribute("/", "dimension"));
  if (file_dimension != dimension)
    refuse("holds a " + std::to_string(file_dimension) + "D run; this scene is " +
           std::to_string(dimension) + "D");
  CouplerCheckpoint checkpoint{.file = *newest,
                               .step = static_cast<std::int64_t>(file.read_attribute("/", "step")),
                               .time = file.read_attribute("/", "time"),
                               .outputs = static_cast<int>(file.read_attribute("/", "outputs")),
                               .fdm = read_solver(file, "fdm"),
                               .mpm = read_solver(file, "mpm")};
  if (!checkpoint.fdm) refuse("names no FDM checkpoint (attribute fdm_path)");
  return checkpoint;
}

}  // namespace mpfd::coupler
