#pragma once
// The project's exception types (pmp-library style): each says what is wrong in words a
// user can act on. Caught per model at the graph boundary; see README "Exit codes".

#include <stdexcept>
#include <string>

namespace papercraft {

/// The input (a mesh file, a parameter, a job) is malformed or violates a precondition.
class InvalidInputException : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A file could not be read or written.
class IOException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A mesh has a topology an algorithm cannot handle (non-manifold, wrong boundary count).
class TopologyException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical solver failed (factorisation, non-convergence).
class SolverException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A part cannot be approximated within the tolerance (refinement guard tripped).
class ApproximationException : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A configuration (YAML) error; the message carries file:line:column.
class ConfigException : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A broken invariant of papercraft itself (a node emitting on a port it did not declare, a
/// parameter read that was never declared): a bug, never the input's fault. The runner exits
/// with code 3 ("internal error") when one occurs.
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace papercraft
