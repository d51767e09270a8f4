#include "cosim/serving/checkpoint_reader.hpp"

#include <cmath>

#include "cosim/serving/protocol_error.hpp"

namespace mpfd::cosim {

CheckpointReader::CheckpointReader(const std::filesystem::path& path)
    : h5_(path, io::Hdf5File::Mode::read) {}

void CheckpointReader::mismatch(const std::string& what) const {
  throw ProtocolError(cosim::v1::ERROR_CODE_IO, "Restore: '" + h5_.path().string() + "' " + what,
                      false);
}

std::vector<double> CheckpointReader::values(const std::string& name, std::size_t count,
                                             const std::string& of) const {
  if (!h5_.exists(name)) mismatch("has no array '" + name + "'");
  auto values = h5_.read_dataset(name).values;
  if (values.size() != count)
    mismatch("array '" + name + "' has " + std::to_string(values.size()) + " values; expected " +
             std::to_string(count) + " (" + of + ")");
  return values;
}

std::vector<int> CheckpointReader::indices(const std::string& name, std::size_t count,
                                           const std::string& of, int limit,
                                           std::optional<int> special,
                                           const std::string& meaning) const {
  const std::vector<double> read = values(name, count, of);
  std::vector<int> out(read.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    const double v = read[i];
    const bool whole = v == std::floor(v);
    if (!(whole && ((v >= 0 && v < limit) || (special && v == *special))))
      mismatch("array '" + name + "' holds " + std::to_string(v) + " at " + std::to_string(i) +
               "; expected " + meaning);
    out[i] = static_cast<int>(v);
  }
  return out;
}

}  // namespace mpfd::cosim
