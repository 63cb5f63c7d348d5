// IR JSON (docs/ir.md): sorted keys, exact number round trip, byte-stable output, locale-proof.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <clocale>
#include <cstdlib>
#include <locale>
#include <random>
#include <sstream>

#include "model_test_support.hpp"
#include "rbdc/ir_json.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

using ::testing::HasSubstr;

const std::string kMiniCheetah = test::source_path("robots/mini_cheetah.urdf");

// A numpunct that writes a decimal comma, as some locales do.
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
};

TEST(IrJson, NumbersRoundTripExactly) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  for (int k = 0; k < 10000; ++k) {
    const double x = std::ldexp(mantissa(rng), exponent(rng) / 10);
    const std::string s = json_number(x);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
  }
  EXPECT_EQ(json_number(0.1), "0.10000000000000001");  // 17 significant digits
  EXPECT_EQ(json_number(-2), "-2");
}

TEST(IrJson, KeysAreSortedAndValuesComeFromTheModel) {
  const Model m = load_urdf(kMiniCheetah);
  const std::string ir = to_ir_json(m);
  // Top-level keys are the lines indented by exactly two spaces.
  std::vector<std::string> keys;
  std::istringstream lines(ir);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  \"", 0) == 0) keys.push_back(line.substr(3, line.find('"', 3) - 3));
  }
  const std::vector<std::string> expected = {"PRED", "SUCC", "bodies", "couplings", "feet", "floating_base",
                                             "format", "frames", "gravity", "joints", "kappa", "lambda", "mu", "name",
                                             "nb", "nq", "nu", "nv"};
  EXPECT_EQ(keys, expected);
  EXPECT_THAT(ir, HasSubstr("\"format\": \"rbdc-ir-1\""));
  EXPECT_THAT(ir, HasSubstr("\"PRED\": [0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11]"));
  EXPECT_THAT(ir, HasSubstr("\"lower\": null"));
  EXPECT_THAT(ir, HasSubstr("\"couplings\": []"));
  // Every body mass reads back exactly, in order.
  const std::string tag = "\"mass\": ";
  size_t i = 0;
  for (size_t at = ir.find(tag); at != std::string::npos; at = ir.find(tag, at + 1), ++i) {
    ASSERT_LT(i, m.bodies.size());
    EXPECT_EQ(std::strtod(ir.c_str() + at + tag.size(), nullptr), m.bodies[i].mass);
  }
  EXPECT_EQ(i, m.bodies.size());
}

TEST(IrJson, ByteStableAcrossLoadsAndLocales) {
  const std::string first = to_ir_json(load_urdf(kMiniCheetah));
  EXPECT_EQ(first, to_ir_json(load_urdf(kMiniCheetah)));
  const std::locale previous = std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  const std::string with_comma_locale = to_ir_json(load_urdf(kMiniCheetah));
  std::locale::global(previous);
  EXPECT_EQ(first, with_comma_locale);
}

TEST(IrJson, NamesAreEscaped) {
  Model m = load_urdf(kMiniCheetah);
  m.bodies[0].name = "a\"b\\c\n";
  EXPECT_THAT(to_ir_json(m), HasSubstr("\"name\": \"a\\\"b\\\\c\\u000a\""));
}

}  // namespace
}  // namespace rbdc
