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

} // namespace test
} // namespace segmat
