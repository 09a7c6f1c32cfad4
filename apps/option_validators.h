// Strict numbers on the command line (docs/cli.md, "Options"). CLI11 converts integers with
// strtoll base 0 ("--count 010" was 8, "0x10" 16) and floats with strtod ("nan", "inf", hex
// floats), and its PositiveNumber check lets NaN through. Every numeric option of every command
// (CLI11 type INT, UINT or FLOAT, also inside lists such as --box) is therefore checked first:
// decimal digits only, no leading zeros on integers, no sign on unsigned ones, a finite value.
// Option values that the commands parse themselves (--fix radius=2, --grid 3x3x2, --shard 1/4,
// --vertex-normal 1=0,0,1) use ParseDecimal / ParseDecimalInteger, with the same rules.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace implicitfit {

// Adds the strict check to every numeric option of `app` and of its subcommands (call after
// every command has registered its options).
void MakeNumberOptionsStrict(CLI::App& app);

// `text` as a finite decimal number; InputError "<what>: ..." otherwise.
double ParseDecimal(const std::string& text, const std::string& what);
// `text` as a decimal integer in [min, max]; InputError "<what>: ..." otherwise.
long long ParseDecimalInteger(const std::string& text, const std::string& what, long long min,
                              long long max);

// The reason `text` is not a strict decimal of the kind ("" when it is one).
std::string StrictNumberProblem(const std::string& text, bool integer, bool allow_sign);

}  // namespace implicitfit
