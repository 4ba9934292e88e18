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

/** \brief segmat_mesh's arguments for the bundled teddy with the authors' medial meshes, writing
 * to \a prefix: "data/teddy/teddy.off -b teddy_mat.ma -s teddy_smat.ma -o PREFIX".
 */
std::string
teddyMeshArgs(const std::string& prefix);

} // namespace test
} // namespace segmat
