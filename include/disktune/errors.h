// SPDX-License-Identifier: GPL-3.0-or-later
// The exceptions disktune throws. Each carries a sentence a user can act on: what is
// wrong, where, and what to do, in the library's terms (never a front end's flags or
// commands). Front ends map each kind to its own exit code.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace disktune {

/// Base of every disktune error.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A parameter or an input file's content is not acceptable.
struct InvalidInput : Error {
  /// What the message asks the caller to change, when that is one of the call's
  /// parameters other than the one at fault: the message says so in the library's
  /// words, and a front end may add its own name for it (the command line adds its
  /// flag). `sample`: start from a packing the library sampled (sampling.h,
  /// surface_sampling.h). `memory`: larger radii, a smaller domain, or more memory
  /// allowed than the machine reports (check_resources, resources.h).
  enum class Remedy { none, radius, sizing, domain, box_size, sample, memory };

  explicit InvalidInput(const std::string& what, Remedy remedy = Remedy::none, std::string value = {})
      : Error(what), remedy_(remedy), value_(std::move(value)) {}

  Remedy remedy() const { return remedy_; }
  /// The value the message suggests for that parameter ("0.03" for a radius), or empty.
  const std::string& value() const { return value_; }

 private:
  Remedy remedy_;
  std::string value_;
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
