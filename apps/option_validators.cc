#include "apps/option_validators.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "datasets/io/io_error.h"

namespace implicitfit {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string StrictNumberProblem(const std::string& text, bool integer, bool allow_sign) {
  const std::string shown = "'" + text.substr(0, 40) + "'";
  size_t i = 0;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) {
    if (!allow_sign && text[i] == '-') return shown + " must not be negative";
    ++i;
  }
  const size_t digits_begin = i;
  while (i < text.size() && IsDigit(text[i])) ++i;
  const size_t int_digits = i - digits_begin;
  if (integer) {
    if (int_digits == 0 || i != text.size())
      return shown + " is not a decimal integer";
    if (int_digits > 1 && text[digits_begin] == '0')
      return shown + ": leading zeros are not allowed (decimal numbers only)";
    if (int_digits > 18) return shown + " is out of range";
    return "";
  }
  size_t frac_digits = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && IsDigit(text[i])) ++i, ++frac_digits;
  }
  if (int_digits + frac_digits == 0) return shown + " is not a decimal number";
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    const size_t exp_begin = i;
    while (i < text.size() && IsDigit(text[i])) ++i;
    if (i == exp_begin) return shown + " is not a decimal number";
  }
  if (i != text.size()) return shown + " is not a decimal number";
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v)) return shown + " is out of the range of a double";
  return "";
}

double ParseDecimal(const std::string& text, const std::string& what) {
  const std::string problem = StrictNumberProblem(text, false, true);
  if (!problem.empty()) throw InputError(what + ": " + problem);
  return std::strtod(text.c_str(), nullptr);
}

long long ParseDecimalInteger(const std::string& text, const std::string& what, long long min,
                              long long max) {
  const std::string problem = StrictNumberProblem(text, true, true);
  if (!problem.empty()) throw InputError(what + ": " + problem);
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (v < min || v > max)
    throw InputError(what + ": " + text + " is outside " + std::to_string(min) + ".." +
                     std::to_string(max));
  return v;
}

void MakeNumberOptionsStrict(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    const bool integer = type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0;
    const bool unsigned_int = type.rfind("UINT", 0) == 0;
    const bool floating = type.rfind("FLOAT", 0) == 0;
    if (!integer && !floating) continue;
    option->check(
        [integer, unsigned_int](const std::string& value) {
          return StrictNumberProblem(value, integer, !unsigned_int);
        },
        "");
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    MakeNumberOptionsStrict(*sub);
}

}  // namespace implicitfit
