#include "common/core/error.hpp"

namespace mpfd {

void fail_invariant(const char* expression, const std::string& message,
                    std::source_location where) {
  throw InvariantError(std::string("internal error: ") + expression + " failed at " +
                       where.file_name() + ":" + std::to_string(where.line()) + " in " +
                       where.function_name() + ": " + message);
}

}  // namespace mpfd
