#pragma once
// The two error channels of MPFD (docs/STYLE): user errors are exceptions of
// type mpfd::Error (or a subclass) with a message naming the key, the value and
// the rule; broken invariants are MPFD_ASSERT, which names the expression and
// the source location. Only main() turns either into an exit code.

#include <stdexcept>
#include <string>

namespace mpfd {

/// A user-facing error: bad input, a failed peer, a numerical breakdown.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by MPFD_ASSERT: a bug in MPFD, not in the user's input.
class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

[[noreturn]] void fail_invariant(const char* expression, const std::string& message,
                                 const char* file, int line, const char* function);

}  // namespace mpfd

/// Checks an invariant in every build type (cheap checks only; never in inner loops).
#define MPFD_ASSERT(expr, message)                                                       \
  do {                                                                                   \
    if (!(expr)) ::mpfd::fail_invariant(#expr, (message), __FILE__, __LINE__, __func__); \
  } while (false)
