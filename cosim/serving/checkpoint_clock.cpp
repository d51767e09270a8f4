#include "cosim/serving/checkpoint_clock.hpp"

#include <cmath>
#include <string>

#include "common/core/require.hpp"

namespace mpfd::cosim {

void write_checkpoint_clock(io::Hdf5File& h5, const CheckpointClock& clock) {
  h5.write_attribute("/", "time", clock.start_time + clock.solver_time);
  h5.write_attribute("/", "solver_time", clock.solver_time);
  h5.write_attribute("/", "setup_start_time", clock.setup_start_time);
  h5.write_attribute("/", "start_time", clock.start_time);
  h5.write_attribute("/", "step", clock.steps);
}

CheckpointClock read_checkpoint_clock(const CheckpointReader& in, std::uint64_t step,
                                      double setup_start_time) {
  const io::Hdf5File& h5 = in.file();
  CheckpointClock clock;
  const double steps = h5.read_attribute("/", "step");
  if (steps != static_cast<double>(step))
    in.mismatch("was taken at step " + std::to_string(static_cast<long long>(steps)) +
                "; the Restore request says step " + std::to_string(step));
  clock.steps = static_cast<std::int64_t>(steps);
  clock.setup_start_time = h5.read_attribute("/", "setup_start_time");
  if (clock.setup_start_time != setup_start_time)
    in.mismatch("was taken in a zone set up with start_time " +
                shortest_text(clock.setup_start_time) + " s; Setup gave " +
                shortest_text(setup_start_time) + " s");
  clock.start_time = h5.read_attribute("/", "start_time");
  if (!std::isfinite(clock.start_time))
    in.mismatch("has start_time " + shortest_text(clock.start_time) +
                "; it becomes the zone's clock and must be finite");
  clock.solver_time = h5.read_attribute("/", "solver_time");
  if (!(clock.solver_time >= 0.0) || !std::isfinite(clock.solver_time))
    in.mismatch("has solver_time " + shortest_text(clock.solver_time) +
                " s; expected a finite time >= 0 advanced since Setup");
  return clock;
}

}  // namespace mpfd::cosim
