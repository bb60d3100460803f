// SPDX-License-Identifier: GPL-3.0-or-later
// The exceptions disktune throws. Each carries a sentence a user can act on: what is
// wrong, where, and what to do. Front ends map each kind to its own exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace disktune {

/// Base of every disktune error.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A parameter or an input file's content is not acceptable.
struct InvalidInput : Error {
  using Error::Error;
};

/// A file could not be read or written.
struct IoError : Error {
  using Error::Error;
};

/// A result failed disktune's own final check (conflict-free and maximal): a bug in
/// disktune. The message says which check failed and where.
struct InternalError : Error {
  using Error::Error;
};

/// A long operation was stopped by its caller (a progress callback returned false).
/// The operation left what it worked on as it was before it started.
struct Cancelled : Error {
  using Error::Error;
};

}  // namespace disktune
