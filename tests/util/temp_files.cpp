#include <util/temp_files.h>

#include <segmat/common/error.h>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

namespace segmat {
namespace test {

namespace {
// The per-process directory, removed with everything in it when the test program exits.
struct ScratchDirectory
{
  std::string path;
  ScratchDirectory()
  {
    std::string base = ::testing::TempDir();
    if (base.empty() || base.back() != '/')
      base += '/';
    path = base + "segmat_test_" + std::to_string(::getpid()) + "/";
    std::filesystem::create_directories(path);
  }
  ~ScratchDirectory()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};
} // namespace

std::string
scratchDir()
{
  static const ScratchDirectory dir;
  return dir.path;
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
      return ::testing::AssertionFailure()
             << "path is '" << e.path() << "', not '" << path << "': " << what;
    if (e.line() != line)
      return ::testing::AssertionFailure()
             << "line is " << e.line() << ", not " << line << ": " << what;
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

::testing::AssertionResult
loadingFails(const std::function<void(const std::string& path)>& load, const std::string& name,
             const std::string& bytes, long line, const std::string& needle)
{
  const std::string path = writeScratchFile(name, bytes);
  return throwsFileError([&] { load(path); }, path, line, needle);
}

::testing::AssertionResult
damagedCopiesFailCleanly(const std::string& name, const std::string& bytes,
                         const std::function<void(const std::string& path)>& load)
{
  std::vector<std::string> copies;
  const std::size_t step = std::max<std::size_t>(1, bytes.size() / 200);
  for (std::size_t n = 0; n < bytes.size(); n += step)
    copies.push_back(bytes.substr(0, n));
  std::mt19937 rng(12345);
  const char replacements[] = {'\0', '\n', ' ', '-', '9', 'x', '#', '\xff'};
  for (int i = 0; i < 200 && !bytes.empty(); ++i) {
    std::string copy = bytes;
    copy[rng() % copy.size()] = replacements[rng() % sizeof replacements];
    copies.push_back(copy);
  }
  int errors = 0;
  for (std::size_t i = 0; i < copies.size(); ++i) {
    const std::string path = writeScratchFile(name, copies[i]);
    try {
      load(path);
    } catch (const segmat::Error&) {
      ++errors;
    } catch (const std::exception& e) {
      return ::testing::AssertionFailure() << "copy " << i << " threw " << e.what();
    }
  }
  return ::testing::AssertionSuccess() << errors << " of " << copies.size() << " copies rejected";
}

} // namespace test
} // namespace segmat
