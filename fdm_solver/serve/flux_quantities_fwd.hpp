#pragma once
// Forward declaration of the v1.1 flux quantities (flux_quantities.hpp).

namespace mpfd::fdm {
enum class FluxQuantity;
}  // namespace mpfd::fdm
