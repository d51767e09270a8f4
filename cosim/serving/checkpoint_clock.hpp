#pragma once
// A zone's clock as both solvers' checkpoints keep it (root attributes `time`,
// `solver_time`, `setup_start_time`, `start_time`, `step`). The zone's start
// time is Setup's until an Activate of a dormant zone or a commit of imported
// fields moves it (proto/README.md §5, §15 rule 4), so a checkpoint keeps both:
// Restore checks Setup's against the running zone's and takes the zone's.

#include <cstdint>

#include "common/io/hdf5_file.hpp"
#include "cosim/serving/checkpoint_reader.hpp"

namespace mpfd::cosim {

struct CheckpointClock {
  std::int64_t steps = 0;
  double solver_time = 0.0;       ///< [s] advanced since Setup
  double start_time = 0.0;        ///< [s] the zone's; its coupled time is this + solver_time
  double setup_start_time = 0.0;  ///< [s] Setup.start_time
};

void write_checkpoint_clock(io::Hdf5File& h5, const CheckpointClock& clock);

/// The clock of the checkpoint `in`, checked against the Restore request's `step`
/// and the running zone's `setup_start_time`; its start_time must be finite.
/// Throws as CheckpointReader::mismatch.
[[nodiscard]] CheckpointClock read_checkpoint_clock(const CheckpointReader& in, std::uint64_t step,
                                                    double setup_start_time);

}  // namespace mpfd::cosim
