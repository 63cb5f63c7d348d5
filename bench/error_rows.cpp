// The error studies' statistics and JSON rows (error_rows.hpp).
#include "error_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace rbdc_bench {
namespace {

std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

}  // namespace

Statistics statistics(std::vector<double> errors) {
  Statistics s;
  if (errors.empty()) return s;
  std::sort(errors.begin(), errors.end(), [](double a, double b) {
    return std::isnan(b) || (!std::isnan(a) && a < b);  // NaN sorts last and so becomes the max
  });
  s.max = errors.back();
  s.median = errors[errors.size() / 2];
  return s;
}

int states_argument(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--states") == 0) return std::atoi(argv[i + 1]);
  return 1000;
}

void print_study_start(int states, const char* reference) {
  std::printf("{\"states\": %d, \"reference\": \"%s\", \"rows\": [", states, reference);
}

void print_row(const ErrorRow& row, bool& first_row) {
  std::printf("%s\n    {\"robot\": \"%s\", \"quantity\": \"%s\", \"part\": \"%s\", \"variant\": \"%s\", "
              "\"bench\": \"%s\", \"ground_mass\": %s, \"ground_mass_over_total\": %s, \"max\": %s, "
              "\"median\": %s}",
              first_row ? "" : ",", row.robot.c_str(), row.quantity.c_str(), row.part.c_str(),
              row.variant.c_str(), row.bench.c_str(), json_number(row.ground_mass).c_str(),
              json_number(row.ground_mass_over_total).c_str(), json_number(row.errors.max).c_str(),
              json_number(row.errors.median).c_str());
  first_row = false;
}

void print_study_end() { std::printf("\n]}\n"); }

}  // namespace rbdc_bench
