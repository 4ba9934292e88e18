/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <sys/types.h>

/// An X display that VTK can draw on, for as long as this object lives.
///
/// Debian's VTK draws through X (GLX) only and calls abort() when it cannot open the display or
/// the display has no GLX, so the display is checked here first and a fault becomes an error
/// message. With DISPLAY set, that display is used. Without, a private Xvfb is started (Mesa's
/// software OpenGL); a server that does not accept a GLX client within about a second is
/// replaced, at most twice. The checking connection stays open while the object lives: an X
/// server resets when its last client leaves and drops the clients that arrive meanwhile, which
/// would be VTK's.
class XDisplay
{
public:
  /// \throws segmat::Error naming the display and what is wrong with it
  XDisplay();
  ~XDisplay();
  XDisplay(const XDisplay&) = delete;
  XDisplay&
  operator=(const XDisplay&) = delete;

private:
  void
  stopServer();
  void* connection_ = nullptr; ///< Display*: Xlib's macros stay out of this header
  pid_t server_ = 0;
};
