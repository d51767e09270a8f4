#pragma once
// How much the coupler's deposit takes from the FDM cells beside the coupling
// face (cells k-w). While the flow leaves the MPM zone, those cells get the
// particles that cross the face (T (4-19)...(4-21)) and the coupler takes back
// the FDM's own flux through it (returned parcels, handshake/injection_flux.hpp).
// Where the MPM's gas moves out more slowly than the FDM's, the particles bring
// less than is taken back, the cell empties, and the FDM stops with a negative
// density at any step size or grid (docs/stability.md, random scenes case 5).
// The watch keeps the worst cell of the last two deposits, to name that cause in
// the run's error (the FDM or the coupler's strip checks find the empty cell in
// the step after the deposit, or after an output's exchange without advance), and
// the run's worst share, for summary.json.

#include <cstddef>
#include <string>

namespace mpfd::coupler {

/// One face cell's share of a deposit.
struct FaceDrain {
  std::size_t face_cell = 0;
  double share = 0;          ///< of the cell's mass the deposit took (0 where it gained)
  double density = 0;        ///< the cell's density before the deposit [kg/m^3]
  double taken_back = 0;     ///< the FDM's flux out of the zone the coupler took back [kg]
  double particle_mass = 0;  ///< mass of the particles that crossed into the cell [kg]
};

/// `error`, then `cause` (FaceDrainWatch::cause_text) as its next sentence.
[[nodiscard]] std::string with_cause(const std::string& error, const std::string& cause);

class FaceDrainWatch {
 public:
  /// A deposit taking at least this share of a face cell's mass is named in an error.
  static constexpr double kNamedShare = 0.5;

  /// Forgets the deposit before the last; call before observing the face cells of a new one.
  void start_deposit() {
    previous_ = last_;
    last_ = {};
  }
  /// Face cell `face_cell` of density `density` [kg/m^3] and volume `cell_volume`
  /// [m^3] gets `added_density` [kg/m^3] from the deposit, `returned_mass` [kg] of
  /// it the returned parcel (negative: the FDM's outflow taken back).
  void observe(std::size_t face_cell, double density, double added_density, double returned_mass,
               double cell_volume);

  /// The face cell the last deposit took the largest share of.
  [[nodiscard]] const FaceDrain& last() const { return last_; }
  /// The face cell either of the last two deposits took the largest share of.
  [[nodiscard]] const FaceDrain& worst() const {
    return previous_.share > last_.share ? previous_ : last_;
  }
  /// The largest share any deposit of the run took from a face cell.
  [[nodiscard]] double run_max_share() const { return run_max_share_; }
  /// The deposit before the last one's worst face cell (for a checkpoint).
  [[nodiscard]] const FaceDrain& previous() const { return previous_; }
  /// A restarted run's watch goes on from what its checkpoint recorded.
  void resume(const FaceDrain& last, const FaceDrain& previous, double run_max_share) {
    last_ = last;
    previous_ = previous;
    run_max_share_ = run_max_share;
  }
  /// Why the FDM cell `cell` (worst()'s, its index and position as text) emptied, when
  /// one of the last two deposits took at least kNamedShare of it; empty otherwise.
  [[nodiscard]] std::string cause_text(const std::string& cell) const;

 private:
  FaceDrain last_, previous_;
  double run_max_share_ = 0;
};

}  // namespace mpfd::coupler
