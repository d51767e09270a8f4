#include "common/core/error.hpp"

namespace mpfd {

void fail_invariant(const char* expression, const std::string& message, const char* file, int line,
                    const char* function) {
  throw InvariantError(std::string("internal error: ") + expression + " failed at " + file + ":" +
                       std::to_string(line) + " in " + function + ": " + message);
}

}  // namespace mpfd
