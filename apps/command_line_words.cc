#include "apps/command_line_words.h"

#include <algorithm>
#include <cctype>

namespace implicitfit {
namespace {

// Levenshtein distance (insertions, deletions, substitutions), two rows.
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      current[j] = std::min(
          {previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// Long names ("--model") and short names ("-h") of the options of `app`.
void AddOptionNames(const CLI::App& app, std::vector<std::string>* names) {
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names->push_back("--" + name);
    for (const std::string& name : option->get_snames()) names->push_back("-" + name);
  }
}

// A word that is an option's name rather than a value: "--name" or "-x". Longer single-dash
// words ("-1e3", "-1,2,3", "-nan", "-inf") are values, whose problems CLI11 and the strict
// number checks name with their option; a lone "-" is a value too.
bool LooksLikeOption(const std::string& word) {
  if (word.size() < 2 || word[0] != '-') return false;
  if (word[1] == '-') return word.size() > 2;
  return word.size() == 2 && !std::isdigit(static_cast<unsigned char>(word[1])) && word[1] != '.';
}

std::string OptionName(const std::string& word) { return word.substr(0, word.find('=')); }

std::string DidYouMean(const std::string& word, const std::vector<std::string>& known) {
  const std::string closest = ClosestName(word, known);
  return closest.empty() ? "" : " (did you mean " + closest + "?)";
}

}  // namespace

std::string ClosestName(const std::string& word, const std::vector<std::string>& known) {
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const std::string& name : known) {
    const size_t d = EditDistance(word, name);
    if (d < best_distance) best_distance = d, best = name;
  }
  return best;
}

std::string CommandName(const CLI::App& app, const std::vector<std::string>& words) {
  for (const std::string& word : words) {
    if (word == "--") break;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == word) return word;
  }
  return "";
}

std::string UnknownCommandLineWord(const CLI::App& app, const std::vector<std::string>& words) {
  std::vector<std::string> commands, tool_options;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    commands.push_back(sub->get_name());
  AddOptionNames(app, &tool_options);
  std::string command_list;
  for (const std::string& c : commands) command_list += (command_list.empty() ? "" : ", ") + c;
  // Before the command: only the tool's own options (and their values).
  size_t i = 0;
  const CLI::App* command = nullptr;
  for (; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word == "--") return "";
    if (LooksLikeOption(word)) {
      const std::string name = OptionName(word);
      if (std::find(tool_options.begin(), tool_options.end(), name) == tool_options.end())
        return "implicitfit: unknown option " + name + DidYouMean(name, tool_options) +
               "; the command comes first: implicitfit COMMAND [options] (" + command_list + ")";
      continue;
    }
    if (std::find(commands.begin(), commands.end(), word) != commands.end()) {
      command = app.get_subcommand(word);
      break;
    }
    // The value of a tool option ("--max-points 10 fit ..."), or a word that is no command.
    if (i > 0 && LooksLikeOption(words[i - 1]) && words[i - 1].find('=') == std::string::npos)
      continue;
    const std::string closest = ClosestName(word, commands);
    return "implicitfit: unknown command '" + word + "'" +
           (closest.empty() ? "" : " (did you mean '" + closest + "'?)") +
           "; commands: " + command_list;
  }
  if (!command) return "";
  std::vector<std::string> known = tool_options;  // the tool's limits may follow the command
  AddOptionNames(*command, &known);
  for (++i; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word == "--") break;
    if (!LooksLikeOption(word)) continue;
    const std::string name = OptionName(word);
    if (std::find(known.begin(), known.end(), name) == known.end())
      return "implicitfit " + command->get_name() + ": unknown option " + name +
             DidYouMean(name, known) + "; implicitfit " + command->get_name() +
             " --help lists them";
  }
  return "";
}

}  // namespace implicitfit
