#include <util/run_program.h>
#include <util/temp_files.h>

#include <sys/wait.h>

#include <cstdlib>

namespace segmat {
namespace test {

ProgramRun
runProgram(const std::string& program, const std::string& args)
{
  const std::string out = scratchDir() + program + ".out", err = scratchDir() + program + ".err";
  const std::string cmd =
      std::string(SEGMAT_BIN_DIR) + "/" + program + " " + args + " >" + out + " 2>" + err;
  const int raw = std::system(cmd.c_str());
  ProgramRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = readWholeFile(out);
  run.err = readWholeFile(err);
  return run;
}

std::string
teddyMeshArgs(const std::string& prefix)
{
  const std::string teddy = std::string(SEGMAT_DATA_DIR) + "/teddy/";
  return teddy + "teddy.off -b " + teddy + "teddy_mat.ma -s " + teddy + "teddy_smat.ma -o " +
         prefix;
}

} // namespace test
} // namespace segmat
