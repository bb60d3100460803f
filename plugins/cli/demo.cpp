// SPDX-License-Identifier: GPL-3.0-or-later
// The built-in default job: what `disktune` with no arguments shows a new user.
#include <cstdio>
#include <filesystem>

#include "commands.h"

namespace disktune::cli {

int run_demo() {
  std::filesystem::create_directories("disktune-demo");
  say("disktune demo: an MPS of the unit periodic square at r = 0.01, tuned to eta = 0.80 "
              "(see disktune --help)\n");
  SampleJob sample;
  sample.domain.radius = 0.01;
  sample.domain.has_radius = true;
  sample.domain.guarded = true;
  sample.output = "disktune-demo/mps.csv";
  sample.svg = "disktune-demo/mps.svg";
  if (const int rc = with_outputs_as_one([&] { return run_sample(sample); }); rc != kExitOk) return rc;

  TuneJob tune;
  tune.domain = sample.domain;
  tune.target = Target::area_fraction(0.80);
  tune.input = sample.output;
  tune.output = "disktune-demo/tuned.csv";
  tune.svg = "disktune-demo/tuned.svg";
  return with_outputs_as_one([&] { return run_tune(tune); });
}

}  // namespace disktune::cli
