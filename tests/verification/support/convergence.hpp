#pragma once
// Observed order of accuracy from a sequence of runs (after MFEM's
// ConvergenceStudy). Entries are (N, error) with N the number of cells along
// one axis (or any count proportional to 1/h) and the model
//   error = C N^-p.
// Between consecutive entries i-1 and i the observed order is
//   p_i = ln(error_{i-1} / error_i) / ln(N_i / N_{i-1}),
// and the fitted order is -slope of the least-squares line through
// (ln N, ln error). To study a mesh size h, add N = 1 / h.

#include <cstddef>
#include <vector>

namespace mpfd::verification {

class ConvergenceStudy {
 public:
  /// Appends a run; throws mpfd::Error unless cells > 0, error > 0 (both
  /// finite) and cells differs from the previous entry's.
  void add(double cells, double error);

  [[nodiscard]] std::size_t size() const { return cells_.size(); }
  /// size() - 1 orders p_i, i = 1 .. size() - 1, in the order added.
  [[nodiscard]] std::vector<double> observed_orders() const;
  /// p of the least-squares fit; throws mpfd::Error with fewer than two entries.
  [[nodiscard]] double fitted_order() const;
  /// C of the least-squares fit error = C N^-p.
  [[nodiscard]] double fitted_constant() const;

 private:
  struct Fit {
    double order;
    double constant;
  };
  [[nodiscard]] Fit fit() const;

  std::vector<double> cells_;
  std::vector<double> errors_;
};

}  // namespace mpfd::verification
