// Runs one of the built command-line programs (SEGMAT_BIN_DIR) and captures what it printed.
#pragma once

#include <string>

namespace segmat {
namespace test {

/** \brief Exit status and output of a program run. */
struct ProgramRun
{
  int status = -1;  ///< exit code (-1 when it did not exit normally)
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/** \brief Runs SEGMAT_BIN_DIR/\a program with \a args (a shell-quoted string) and captures its
 * standard output and error through scratch files.
 */
ProgramRun
runProgram(const std::string& program, const std::string& args);

} // namespace test
} // namespace segmat
