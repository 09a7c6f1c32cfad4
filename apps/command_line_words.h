// Words of the command line that no command or option of the tool takes, found before CLI11
// parses. CLI11 checks a command's required options before it reports the words it did not
// expect, so `fit c.xyz --modle sphere` said "--out is required" and hid the typo; and an unknown
// command was "The following argument was not expected". These checks name the word first, with
// the closest known name when one is near (edit distance at most 2, or a third of its length).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace implicitfit {

// The problem with the command line `words` (argv without the program name), as the line to
// print ("implicitfit: unknown command 'fitt' (did you mean 'fit'?); commands: ..." or
// "implicitfit fit: unknown option --modle (did you mean --model?); ..."), or "" when every
// command and option word is known. Option values are not checked (that is CLI11's work); words
// after "--" are values.
std::string UnknownCommandLineWord(const CLI::App& app, const std::vector<std::string>& words);

// The command `words` name (the first word that is one of app's commands), or "".
std::string CommandName(const CLI::App& app, const std::vector<std::string>& words);

// The name in `known` closest to `word` by edit distance, or "" when none is near enough.
std::string ClosestName(const std::string& word, const std::vector<std::string>& known);

}  // namespace implicitfit
