#include <util/temp_files.h>

#include <segmat/common/error.h>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

namespace segmat {
namespace test {

std::string
scratchDir()
{
  static const std::string dir = [] {
    std::string base = ::testing::TempDir();
    if (base.empty() || base.back() != '/')
      base += '/';
    const std::string d = base + "segmat_test_" + std::to_string(::getpid()) + "/";
    ::mkdir(d.c_str(), 0700);
    return d;
  }();
  return dir;
}

std::string
writeScratchFile(const std::string& name, const std::string& bytes)
{
  const std::string path = scratchDir() + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

std::string
readWholeFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool
fileExists(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

::testing::AssertionResult
throwsFileError(const std::function<void()>& action, const std::string& path, long line,
                const std::string& needle)
{
  try {
    action();
  } catch (const segmat::Error& e) {
    const std::string what = e.what();
    if (e.path() != path)
      return ::testing::AssertionFailure() << "path is '" << e.path() << "', not '" << path
                                           << "': " << what;
    if (e.line() != line)
      return ::testing::AssertionFailure() << "line is " << e.line() << ", not " << line << ": "
                                           << what;
    if (what.find(path) == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks the path: " << what;
    if (line > 0 && what.find(":" + std::to_string(line) + ":") == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks the line: " << what;
    if (what.find(needle) == std::string::npos)
      return ::testing::AssertionFailure() << "message lacks '" << needle << "': " << what;
    return ::testing::AssertionSuccess() << what;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

} // namespace test
} // namespace segmat
