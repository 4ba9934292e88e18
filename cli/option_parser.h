/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Command-line parsing shared by the programs in examples/ and bench/ (not installed).

#include <segmat/common/error.h>

#include <functional>
#include <string>
#include <vector>

namespace segmat {
namespace cli {

/** \brief Exit status of every program (documented in each --help and in docs/cli.md). */
enum ExitCode : int
{
  kExitOk = 0,         ///< success
  kExitFailed = 1,     ///< the computation failed
  kExitBadInput = 2    ///< bad usage, or a missing or malformed input (or output location)
};

/** \brief Bad usage or bad input: the program exits with kExitBadInput. */
class UsageError : public Error
{
public:
  using Error::Error;
};

/** \brief Help-section titles, printed in this order. */
extern const char* const kInput;
extern const char* const kOutput;
extern const char* const kParameters;
extern const char* const kPerformance;

/** \brief One option: one table entry per option, so programs add flags by adding a line. */
struct Option
{
  std::string group;      ///< help section (kInput, kOutput, ... or a title of its own)
  std::string names;      ///< "-g" or "-o, --output" (comma-separated spellings)
  std::string value_name; ///< "" for a flag, else the value's placeholder ("DELTA0")
  std::string help;       ///< one or more lines, without the option's name
  std::function<void(const std::string& value)> apply; ///< called with "" for a flag
};

/** \brief Options, positional arguments and a --help text built from them. */
class OptionParser
{
public:
  /** \param[in] program name in messages ("segmat_mesh")
   * \param[in] synopsis what follows the name in "usage:" ("MESH -o PREFIX [options]")
   * \param[in] summary one paragraph on what the program does
   * \param[in] example one command line that works on the bundled data
   */
  OptionParser(std::string program, std::string synopsis, std::string summary,
               std::string example);

  /** \brief Adds an option taking a value. */
  void
  add(const std::string& group, const std::string& names, const std::string& value_name,
      const std::string& help, std::function<void(const std::string&)> apply);

  /** \brief Adds a flag (no value). */
  void
  flag(const std::string& group, const std::string& names, const std::string& help,
       std::function<void()> apply);

  /** \brief Adds a flag that sets \a target to true. */
  void
  flag(const std::string& group, const std::string& names, const std::string& help, bool& target);

  /** \brief A positional argument (shown in the Input section). */
  void
  positional(const std::string& name, const std::string& help, std::string& target);

  /** \brief Positional arguments after the named ones are appended to \a target. */
  void
  rest(std::vector<std::string>& target);

  /** \brief Adds a free-text paragraph printed at the end of --help (before exit codes). */
  void
  note(const std::string& text);

  /** \brief Parses argv. Returns false when --help was given (the help is then printed on
   * stdout); throws UsageError on an unknown option, a missing value, a bad value (the option's
   * apply may throw Error: it is re-thrown as UsageError naming the option) or a surplus
   * positional argument. Missing positional arguments are the caller's to check.
   */
  bool
  parse(int argc, char** argv);

  /** \brief The full --help text. */
  std::string
  help() const;

  const std::string&
  program() const
  {
    return program_;
  }

private:
  const Option*
  find(const std::string& name) const;

  std::string program_, synopsis_, summary_, example_;
  std::vector<Option> options_;
  std::vector<std::pair<std::string, std::string>> positional_help_;
  std::vector<std::string*> positional_targets_;
  std::vector<std::string>* rest_ = nullptr;
  std::vector<std::string> notes_;
};

/** \name Value parsers: each throws Error("'TEXT' is not ...") without the option's name
 * (OptionParser::parse adds it). */
///@{
/** A finite number. */
double
parseNumber(const std::string& text);
/** A finite number in [lowest, highest]. */
double
parseNumberIn(const std::string& text, double lowest, double highest, const char* what);
/** A whole number in [lowest, highest]. */
long
parseInteger(const std::string& text, long lowest, long highest = 1000000000L);
///@}

/** \brief Options every program shares: --threads, --quiet, --json. */
struct CommonOptions
{
  unsigned threads = 0; ///< 0: all cores (resolved by resolveThreads)
  bool quiet = false;
  bool json = false;
};

/** \brief Registers --quiet and --json (Output) and --threads (Performance) on \a parser. */
void
addCommonOptions(OptionParser& parser, CommonOptions& options, bool with_threads = true);

/** \brief Threads to use: \a requested, or all cores for 0; a request above the machine's core
 * count is clamped with a warning on stderr (one thread per core is the fastest anyway, and
 * per-thread buffers of absurd counts would exhaust memory). */
unsigned
resolveThreads(const std::string& program, unsigned requested);

/** \brief Runs a program's body with the exit-code convention: UsageError → message,
 * "try --help", 2; Error or std::exception → message, 1; std::bad_alloc → "out of memory", 1.
 */
int
runMain(const std::string& program, const std::function<int()>& body);

/** \brief Re-throws any Error from \a load as UsageError (a bad input file exits with 2). */
void
asInput(const std::function<void()>& load);

} // namespace cli
} // namespace segmat
