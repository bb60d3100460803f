// SPDX-License-Identifier: GPL-3.0-or-later
// A muParser formula in x and y, or in x, y and z (internal): what the planar and the
// surface expression sizings evaluate. muParser itself stays in sizing_expression.cpp.
#pragma once

#include <memory>
#include <string>

namespace disktune::detail {

class Formula {
 public:
  /// Parses `expression` over x and y, and z when `with_z`. Throws InvalidInput naming
  /// the position of a syntax error or an unknown variable.
  Formula(const std::string& expression, bool with_z);
  /// The value at (x, y, z); z is ignored without with_z. Copies share one parser;
  /// calls from several threads are serialized.
  double operator()(double x, double y, double z = 0) const;

 private:
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace disktune::detail
