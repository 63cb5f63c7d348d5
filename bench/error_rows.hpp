// What the error studies (error_study.cpp, derivative_error_study.cpp) share: the statistics of a
// variant's errors over the states and the JSON rows bench/report reads,
//   {"robot", "quantity", "part", "variant", "bench": "quantity/implementation" of the case that
//    times the variant, "ground_mass", "ground_mass_over_total" (null unless closed chain), "max", "median"}
// printed inside {"states": N, "reference": "...", "rows": [...]}.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace rbdc_bench {

struct Statistics {
  double max = 0, median = 0;
};

/// Max and median; a NaN error sorts last and so becomes the max.
Statistics statistics(std::vector<double> errors);

struct ErrorRow {
  std::string robot, quantity, part, variant, bench;
  double ground_mass = std::numeric_limits<double>::quiet_NaN();  ///< NaN (printed null) unless closed chain
  double ground_mass_over_total = std::numeric_limits<double>::quiet_NaN();
  Statistics errors;
};

/// The number after --states (default 1000).
int states_argument(int argc, char** argv);

/// Prints the document's opening up to the rows' "[".
void print_study_start(int states, const char* reference);
/// Prints one row, preceded by a comma unless it is the first.
void print_row(const ErrorRow& row, bool& first_row);
/// Closes the rows and the document.
void print_study_end();

}  // namespace rbdc_bench
