// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing functions written as formulas in x and y, evaluated by muParser. muParser stays
// inside this file: public headers only see a Sizing.
#include <muParser.h>

#include <memory>
#include <mutex>
#include <sstream>
#include <string>

#include "disktune/errors.h"
#include "disktune/sizing.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The parser keeps pointers to x and y, so the three live together and never move (a
// copied mu::Parser would still point at the original's variables). Copies of a Sizing
// share one of these. The mutex makes a shared sizing safe to call from several threads:
// evaluation writes x and y.
struct ExpressionState {
  std::string expression;
  mu::Parser parser;
  double x = 0, y = 0;
  std::mutex mutex;

  double operator()(Vec2 p);
};

[[noreturn]] void fail(const std::string& expression, const mu::Parser::exception_type& e) {
  std::ostringstream msg;
  msg << "the sizing expression \"" << expression << "\" is not valid";
  if (e.GetPos() >= 0) msg << " at position " << e.GetPos() << " (0-based)";
  std::string what = e.GetMsg();  // some of muParser's messages end with '.', some not
  if (!what.empty() && what.back() == '.') what.pop_back();
  msg << ": " << what
      << ". Write r with the variables x and y, numbers, + - * / ^, functions such as sin, cos, "
         "exp, sqrt, abs, min, max and the constant pi, e.g. \"0.01 + 0.02*x\"";
  throw InvalidInput(msg.str());
}

double ExpressionState::operator()(Vec2 p) {
  std::lock_guard<std::mutex> lock(mutex);
  x = p.x;
  y = p.y;
  try {
    return parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    fail(expression, e);  // parsing was checked at construction; this is a safety net
  }
}

}  // namespace

Sizing expression_sizing(const std::string& expression) {
  auto state = std::make_shared<ExpressionState>();
  state->expression = expression;
  try {
    state->parser.DefineVar("x", &state->x);
    state->parser.DefineVar("y", &state->y);
    // muParser calls it _pi; people write pi.
    state->parser.DefineConst("pi", kPi);
    state->parser.SetExpr(expression);
    // muParser parses lazily: evaluate once so syntax errors and unknown names fail here,
    // not at the first sample. The value itself is checked where r is sampled.
    state->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    fail(expression, e);
  }
  return Sizing([state](Vec2 p) { return (*state)(p); }, expression);
}

}  // namespace disktune
