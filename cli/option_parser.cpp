/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "option_parser.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <new>
#include <sstream>
#include <thread>

namespace segmat {
namespace cli {

const char* const kInput = "Input";
const char* const kOutput = "Output";
const char* const kParameters = "Parameters";
const char* const kPerformance = "Performance";

namespace {
std::vector<std::string>
spellings(const std::string& names)
{
  std::vector<std::string> out;
  std::stringstream in(names);
  std::string name;
  while (std::getline(in, name, ',')) {
    const auto first = name.find_first_not_of(' ');
    const auto last = name.find_last_not_of(' ');
    if (first != std::string::npos)
      out.push_back(name.substr(first, last - first + 1));
  }
  return out;
}

// "help" lines indented under the option's left column.
void
appendEntry(std::string& out, const std::string& left, const std::string& help)
{
  const std::size_t column = 24;
  std::string line = "  " + left;
  std::stringstream lines(help);
  std::string text;
  bool first = true;
  while (std::getline(lines, text)) {
    if (first && line.size() + 1 < column)
      line += std::string(column - line.size(), ' ');
    else
      line = (first ? line + "\n" : std::string()) + std::string(column, ' ');
    out += line + text + "\n";
    first = false;
  }
  if (first)
    out += line + "\n";
}
} // namespace

OptionParser::OptionParser(std::string program, std::string synopsis, std::string summary,
                           std::string example)
: program_(std::move(program))
, synopsis_(std::move(synopsis))
, summary_(std::move(summary))
, example_(std::move(example))
{
  flag(kOutput, "-h, --help", "print this help and exit", [] {});
}

void
OptionParser::add(const std::string& group, const std::string& names,
                  const std::string& value_name, const std::string& help,
                  std::function<void(const std::string&)> apply)
{
  options_.push_back({group, names, value_name, help, std::move(apply)});
}

void
OptionParser::flag(const std::string& group, const std::string& names, const std::string& help,
                   std::function<void()> apply)
{
  options_.push_back({group, names, "", help, [apply](const std::string&) { apply(); }});
}

void
OptionParser::flag(const std::string& group, const std::string& names, const std::string& help,
                   bool& target)
{
  flag(group, names, help, [&target] { target = true; });
}

void
OptionParser::positional(const std::string& name, const std::string& help, std::string& target)
{
  positional_help_.emplace_back(name, help);
  positional_targets_.push_back(&target);
}

void
OptionParser::rest(std::vector<std::string>& target)
{
  rest_ = &target;
}

void
OptionParser::note(const std::string& text)
{
  notes_.push_back(text);
}

const Option*
OptionParser::find(const std::string& name) const
{
  for (const Option& option : options_)
    for (const std::string& spelling : spellings(option.names))
      if (spelling == name)
        return &option;
  return nullptr;
}

bool
OptionParser::parse(int argc, char** argv)
{
  std::size_t next_positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << help();
      return false;
    }
    if (arg.size() > 1 && arg[0] == '-' && !std::isdigit(static_cast<unsigned char>(arg[1]))) {
      const Option* option = find(arg);
      if (!option)
        throw UsageError("unknown option " + arg);
      std::string value;
      if (!option->value_name.empty()) {
        if (i + 1 >= argc)
          throw UsageError("option " + arg + " needs a value (" + option->value_name + ")");
        value = argv[++i];
      }
      try {
        option->apply(value);
      }
      catch (const UsageError&) {
        throw;
      }
      catch (const Error& e) {
        throw UsageError("option " + arg + ": " + e.what());
      }
      continue;
    }
    if (next_positional >= positional_targets_.size() && rest_) {
      rest_->push_back(arg);
      continue;
    }
    if (next_positional >= positional_targets_.size())
      throw UsageError("unexpected argument '" + arg + "'");
    *positional_targets_[next_positional++] = arg;
  }
  return true;
}

std::string
OptionParser::help() const
{
  std::string out = "usage: " + program_ + " " + synopsis_ + "\n\n" + summary_ + "\n\nexample:\n  " +
                    example_ + "\n";
  std::vector<std::string> groups{kInput, kOutput, kParameters, kPerformance};
  for (const Option& option : options_) {
    bool known = false;
    for (const std::string& g : groups)
      known = known || g == option.group;
    if (!known)
      groups.push_back(option.group);
  }
  for (const std::string& group : groups) {
    std::string body;
    if (group == kInput)
      for (const auto& [name, text] : positional_help_)
        appendEntry(body, name, text);
    for (const Option& option : options_)
      if (option.group == group)
        appendEntry(body,
                    option.names + (option.value_name.empty() ? "" : " " + option.value_name),
                    option.help);
    if (!body.empty())
      out += "\n" + group + ":\n" + body;
  }
  for (const std::string& text : notes_)
    out += "\n" + text + "\n";
  out += "\nexit status: 0 success; 1 the computation failed; 2 bad usage, or a missing or\n"
         "malformed input, or an output location that cannot be written.\n";
  return out;
}

double
parseNumber(const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
    throw Error("'" + text + "' is not a number");
  return value;
}

double
parseNumberIn(const std::string& text, double lowest, double highest, const char* what)
{
  const double value = parseNumber(text);
  if (!(value >= lowest && value <= highest))
    throw Error("'" + text + "' is not " + what);
  return value;
}

long
parseInteger(const std::string& text, long lowest, long highest)
{
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno != 0 || value < lowest ||
      value > highest)
    throw Error("'" + text + "' is not a whole number in [" + std::to_string(lowest) + ", " +
                std::to_string(highest) + "]");
  return value;
}

void
addCommonOptions(OptionParser& parser, CommonOptions& options, bool with_threads)
{
  if (with_threads)
    parser.add(kPerformance, "--threads", "T",
             "threads (default 0: all cores; more than the machine's cores are\n"
             "clamped with a warning); the output does not depend on it",
             [&options](const std::string& v) {
               options.threads = static_cast<unsigned>(parseInteger(v, 0, 1000000000L));
             });
  parser.flag(kOutput, "-q, --quiet", "no progress messages on stderr (errors and warnings stay)",
              options.quiet);
  parser.flag(kOutput, "--json", "print one JSON object on stdout instead of the text report",
              options.json);
}

unsigned
resolveThreads(const std::string& program, unsigned requested)
{
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (requested == 0)
    return cores;
  if (requested > cores) {
    std::fprintf(stderr, "%s: warning: --threads %u is more than the machine's %u core(s); using %u\n",
                 program.c_str(), requested, cores, cores);
    return cores;
  }
  return requested;
}

int
runMain(const std::string& program, const std::function<int()>& body)
{
  try {
    return body();
  }
  catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s\n(usage and options: %s --help)\n", program.c_str(), e.what(),
                 program.c_str());
    return kExitBadInput;
  }
  catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: out of memory\n", program.c_str());
    return kExitFailed;
  }
  catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program.c_str(), e.what());
    return kExitFailed;
  }
}

void
asInput(const std::function<void()>& load)
{
  try {
    load();
  }
  catch (const UsageError&) {
    throw;
  }
  catch (const Error& e) {
    if (e.path().empty())
      throw UsageError(e.message());
    throw UsageError(e.path(), e.line(), e.message());
  }
}

} // namespace cli
} // namespace segmat
