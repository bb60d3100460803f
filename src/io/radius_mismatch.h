// SPDX-License-Identifier: GPL-3.0-or-later
// The advice for a packing file whose radii differ from the ones asked for: the file's
// own radii tell whether it was made with one radius or with a sizing.
#pragma once

#include <sstream>

#include "disktune/errors.h"
#include "number_text.h"

namespace disktune::detail {

/// Ends `message` (how a disk's radius differs from the one asked for) with the advice
/// the file supports, and throws it: radii equal to within 1e-6 (`lo`, `hi`: the file's
/// smallest and largest) ask for that radius, radii that vary for the sizing the file
/// was made with. `made` names it: "packing was", "samples were".
[[noreturn]] inline void throw_radius_mismatch(std::ostringstream& message, double lo, double hi, const char* made) {
  if (hi - lo <= 1e-6 * hi) {
    message << "; every disk in the file has that radius: give the radius the " << made << " made with, "
            << number_text(hi);
    throw InvalidInput(message.str(), InvalidInput::Remedy::radius, number_text(hi));
  }
  message << "; the file's radii run from " << number_text(lo) << " to " << number_text(hi)
          << ": give the sizing the " << made << " made with";
  throw InvalidInput(message.str(), InvalidInput::Remedy::sizing);
}

}  // namespace disktune::detail
