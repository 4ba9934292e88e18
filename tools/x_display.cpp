/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * Xlib's macros (None, Status, Bool, ...) clash with VTK and Eigen names, hence a file of its own.
 */
#include "x_display.h"

#include <segmat/common/error.h>

#include <X11/Xlib.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

/// A connection to `name` when the server offers GLX, else null and `fault` says what is wrong.
/// Polled for about a second: an X server resets itself when its last client leaves (unless
/// started with -noreset) and drops the connections that arrive meanwhile.
Display*
connect(const std::string& name, std::string& fault)
{
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (attempt > 0)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    Display* display = XOpenDisplay(name.c_str());
    if (!display) {
      fault = "cannot connect to it";
      continue;
    }
    int opcode = 0, event = 0, error = 0;
    if (XQueryExtension(display, "GLX", &opcode, &event, &error))
      return display;
    XCloseDisplay(display);
    fault = "it has no GLX extension (OpenGL)";
    break;
  }
  return nullptr;
}

/// Starts Xvfb, which picks a free display itself (-displayfd: no race with other servers
/// starting), does not reset when a client leaves (-noreset) and dies with this program
/// (PR_SET_PDEATHSIG). Returns its pid and sets `number`, which stays empty when it did not
/// start.
pid_t
startXvfb(std::string& number)
{
  int fds[2];
  if (pipe(fds) != 0)
    throw segmat::Error(std::string("cannot create a pipe: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    const int null = open("/dev/null", O_RDWR);
    dup2(null, 0);
    dup2(null, 1);
    dup2(null, 2);
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "2048x2048x24", "-nolisten",
           "tcp", "-noreset", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  char c = 0;
  while (pid > 0 && read(fds[0], &c, 1) == 1 && c != '\n')
    number += c;
  close(fds[0]);
  if (number.find_first_not_of("0123456789") != std::string::npos)
    number.clear();
  return pid;
}

} // namespace

XDisplay::XDisplay()
{
  const char* given = std::getenv("DISPLAY");
  if (given && *given) {
    std::string fault;
    connection_ = connect(given, fault);
    if (!connection_)
      throw segmat::Error("cannot draw on X display '" + std::string(given) + "': " + fault +
                          " (unset DISPLAY to draw on a private Xvfb)");
    return;
  }
  std::string fault;
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::string number;
    server_ = startXvfb(number);
    if (number.empty()) { // not installed, or it failed at once: starting it again will not do
      stopServer();
      fault = "Xvfb did not start: install Debian's xvfb, or set DISPLAY";
      break;
    }
    const std::string name = ":" + number;
    connection_ = connect(name, fault);
    if (connection_) {
      setenv("DISPLAY", name.c_str(), 1);
      return;
    }
    fault = "the private Xvfb on " + name + ": " + fault;
    stopServer();
  }
  throw segmat::Error("no X display (DISPLAY is unset) and " + fault);
}

XDisplay::~XDisplay()
{
  if (connection_)
    XCloseDisplay(static_cast<Display*>(connection_));
  stopServer();
}

void
XDisplay::stopServer()
{
  if (server_ <= 0)
    return;
  kill(server_, SIGTERM);
  while (waitpid(server_, nullptr, 0) < 0 && errno == EINTR) {
  }
  server_ = 0;
}
