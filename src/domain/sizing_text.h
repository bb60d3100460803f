// SPDX-License-Identifier: GPL-3.0-or-later
// What the planar and the surface sizing texts share (internal): the text itself, and
// a number in it as one radius everywhere.
#pragma once

#include <string>

#include "../io/number_text.h"
#include "disktune/errors.h"

namespace disktune::detail {

/// The sizing text without surrounding blanks; an empty one is refused, naming the
/// `forms` a sizing of this domain kind can take.
inline std::string sizing_text(const std::string& spec, const std::string& forms) {
  std::string text = trimmed(spec);
  if (text.empty()) throw InvalidInput("the sizing is empty: give " + forms);
  return text;
}

/// True, with the radius in r, when the text is a number: one radius everywhere, which
/// must be positive.
inline bool constant_radius(const std::string& text, double& r) {
  if (!parse_number(text, r)) return false;
  if (!(r > 0)) throw InvalidInput("sizing \"" + text + "\": a constant radius must be positive");
  return true;
}

}  // namespace disktune::detail
