// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing functions written as formulas in x and y (or x, y and z on surfaces), evaluated
// by muParser. muParser stays inside this file: other files only see detail::Formula.
#include <muParser.h>

#include <memory>
#include <mutex>
#include <sstream>
#include <string>

#include "disktune/errors.h"
#include "disktune/sizing.h"
#include "expression_formula.h"

namespace disktune {
namespace detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void fail(const std::string& expression, bool with_z,
                       const mu::Parser::exception_type& e) {
  std::ostringstream msg;
  msg << "the sizing expression \"" << expression << "\" is not valid";
  if (e.GetPos() >= 0) msg << " at position " << e.GetPos() << " (0-based)";
  std::string what = e.GetMsg();  // some of muParser's messages end with '.', some not
  if (!what.empty() && what.back() == '.') what.pop_back();
  msg << ": " << what << ". Write r with the variables " << (with_z ? "x, y and z" : "x and y")
      << ", numbers, + - * / ^, functions such as sin, cos, exp, sqrt, abs, min, max and the "
         "constant pi, e.g. \"0.01 + 0.02*x\"";
  throw InvalidInput(msg.str());
}

}  // namespace

// The parser keeps pointers to x, y and z, so they live together and never move (a
// copied mu::Parser would still point at the original's variables). Copies of a Formula
// share one of these. The mutex makes a shared formula safe to call from several
// threads: evaluation writes x, y and z.
struct Formula::State {
  std::string expression;
  bool with_z = false;
  mu::Parser parser;
  double x = 0, y = 0, z = 0;
  std::mutex mutex;
};

Formula::Formula(const std::string& expression, bool with_z) : state_(std::make_shared<State>()) {
  state_->expression = expression;
  state_->with_z = with_z;
  try {
    state_->parser.DefineVar("x", &state_->x);
    state_->parser.DefineVar("y", &state_->y);
    if (with_z) state_->parser.DefineVar("z", &state_->z);
    // muParser calls it _pi; people write pi.
    state_->parser.DefineConst("pi", kPi);
    state_->parser.SetExpr(expression);
    // muParser parses lazily: evaluate once so syntax errors and unknown names fail here,
    // not at the first sample. The value itself is checked where r is sampled.
    state_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    fail(expression, with_z, e);
  }
}

double Formula::operator()(double x, double y, double z) const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->x = x;
  state_->y = y;
  state_->z = z;
  try {
    return state_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    fail(state_->expression, state_->with_z, e);  // parsing was checked at construction
  }
}

}  // namespace detail

Sizing expression_sizing(const std::string& expression) {
  const detail::Formula formula(expression, false);
  return Sizing([formula](Vec2 p) { return formula(p.x, p.y); }, expression);
}

}  // namespace disktune
